# SPDX-License-Identifier: MIT
# Checks one two-term constant of predicates/adaptive_bounds.hpp (icc_errbound_two_term,
# isp_errbound_two_term, in_ellipse_errbound_two_term) against its Gappa proof
# proofs/gappa/<name>.g; the model and the steps done by hand are in
# proofs/invariants/filters.md ("Two-term stage").
#
#   cmake -DNAME=<proof name> -DCONSTANT=<constant> [-DGAPPA=<gappa>] [-DOUT_DIR=<dir>]
#         -P proofs/check_two_term_constants.cmake
#
# 1. reads CONSTANT = K * kEpsilon * kEpsilon from the header (the single source of truth);
# 2. substitutes K for @K@ in the script and requires Gappa to prove every goal, with no warning
#    that a rewriting hint is not an identity (Gappa would otherwise use it unchecked);
# 3. reports whether K / 2 is proven too. Unlike check_relative_constants.cmake this does not
#    fail: the header's K is kept as it is so that every decision stays the same, and a larger K
#    only sends more calls to the next stage.
cmake_minimum_required(VERSION 3.25)

include("${CMAKE_CURRENT_LIST_DIR}/gappa_common.cmake")
set(header "${source_dir}/predicates/adaptive_bounds.hpp")
set(script "${source_dir}/proofs/gappa/${NAME}.g")
if(NOT EXISTS "${script}")
  message(FATAL_ERROR "no Gappa script ${script}")
endif()
gappa_read_constant("${header}" "${CONSTANT}" "([0-9]+)(\\.0)? \\* kEpsilon \\* kEpsilon" k)

gappa_run("${script}" "K=${k}" rc log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "Gappa does not prove ${CONSTANT} = ${k} u^2 (${script}):\n${log}")
endif()
math(EXPR half "${k} / 2")
gappa_run("${script}" "K=${half}" rc log)
if(rc EQUAL 0)
  message(STATUS "${CONSTANT} = ${k} u^2 is proven; ${half} u^2 would be proven too")
else()
  message(STATUS "${CONSTANT} = ${k} u^2 is proven and ${half} u^2 is not")
endif()
