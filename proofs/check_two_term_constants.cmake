# SPDX-License-Identifier: MIT
# Checks one two-term constant of predicates/adaptive_bounds.hpp (icc_errbound_two_term,
# isp_errbound_two_term) against its Gappa proof proofs/gappa/<name>.g; the model and the steps
# done by hand are in proofs/invariants/filters.md ("Two-term stage").
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

cmake_path(GET CMAKE_CURRENT_LIST_DIR PARENT_PATH source_dir)
set(header "${source_dir}/predicates/adaptive_bounds.hpp")
if(NOT DEFINED GAPPA)
  find_program(GAPPA gappa REQUIRED)
endif()
if(NOT DEFINED OUT_DIR)
  set(OUT_DIR "${CMAKE_CURRENT_BINARY_DIR}")
endif()
set(script "${source_dir}/proofs/gappa/${NAME}.g")
if(NOT EXISTS "${script}")
  message(FATAL_ERROR "no Gappa script ${script}")
endif()

file(STRINGS "${header}" lines REGEX "inline constexpr double ${CONSTANT} = [^;]+;")
list(LENGTH lines count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "${header}: expected exactly one definition of ${CONSTANT}, found ${count}")
endif()
if(NOT lines MATCHES "${CONSTANT} = ([0-9]+)(\\.0)? \\* kEpsilon \\* kEpsilon")
  message(FATAL_ERROR "${header}: ${CONSTANT} must be written <integer>.0 * kEpsilon * kEpsilon")
endif()
set(k "${CMAKE_MATCH_1}")

function(run_gappa k out_rc out_log)
  file(READ "${script}" text)
  string(REPLACE "@K@" "${k}" text "${text}")
  if(text MATCHES "@[A-Z_]+@")
    message(FATAL_ERROR "${script}: unknown placeholder ${CMAKE_MATCH_0}")
  endif()
  set(instance "${OUT_DIR}/${NAME}.instance.g")
  file(WRITE "${instance}" "${text}")
  execute_process(COMMAND "${GAPPA}" "${instance}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(err MATCHES "not trivially equal")
    message(FATAL_ERROR "${script}: a rewriting hint is not an identity:\n${err}")
  endif()
  set(${out_rc} ${rc} PARENT_SCOPE)
  set(${out_log} "${instance}:\n${err}${out}" PARENT_SCOPE)
endfunction()

run_gappa("${k}" rc log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "Gappa does not prove ${CONSTANT} = ${k} u^2 (${script}):\n${log}")
endif()
math(EXPR half "${k} / 2")
run_gappa("${half}" rc log)
if(rc EQUAL 0)
  message(STATUS "${CONSTANT} = ${k} u^2 is proven; ${half} u^2 would be proven too")
else()
  message(STATUS "${CONSTANT} = ${k} u^2 is proven and ${half} u^2 is not")
endif()
