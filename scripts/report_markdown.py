# SPDX-License-Identifier: MIT
"""Markdown helpers shared by the report scripts (adaptation_report.py, stretched_report.py)."""

import math


def fmt(value, digits=3):
    """A number to `digits` significant digits; n/a for None and non-finite values."""
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "n/a"
    return f"{value:.{digits}g}"


def table(header, rows):
    """A Markdown table: the header, then one line per row (cells converted with str)."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)
