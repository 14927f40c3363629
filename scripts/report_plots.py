# SPDX-License-Identifier: MIT
"""Matplotlib helpers shared by the Delaunay reports (delaunay_report.py, delaunay_scaling.py):
the headless backend, the finish of every panel and the saving of a figure."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)


def finish_axes(ax, title, xlabel="N (points)", legend_loc="upper left"):
    """What every panel has: its title, its x axis label, a grid and the legend."""
    ax.set_title(title)
    ax.set_xlabel(xlabel)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc=legend_loc)


def save_figure(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
