# SPDX-License-Identifier: MIT
# Checks one relative-filter constant of predicates/filter_constants.hpp against its Gappa proof
# proofs/gappa/<name>.g; the model is written up in proofs/invariants/filters.md ("Relative
# filters").
#
#   cmake -DNAME=<proof name> -DCONSTANT=<constant> [-DMINIMALITY_NAME=<script>] [-DGAPPA=<gappa>]
#         [-DOUT_DIR=<dir>] -P proofs/check_relative_constants.cmake
#
# 1. reads CONSTANT from the header (the single source of truth); it must be a power of two
#    0x1p±e (so that multiplying a bound by it is exact);
# 2. substitutes it for @EPS@ in the script and requires Gappa to prove the script's goal;
# 3. substitutes half of it and requires Gappa to fail, so the header holds the least power of
#    two this model certifies, not merely some larger proven value (on MINIMALITY_NAME.g when
#    given: a subset of the goals on which Gappa fails fast).
cmake_minimum_required(VERSION 3.25)

include("${CMAKE_CURRENT_LIST_DIR}/gappa_common.cmake")
set(header "${source_dir}/predicates/filter_constants.hpp")
set(script "${source_dir}/proofs/gappa/${NAME}.g")
if(NOT EXISTS "${script}")
  message(FATAL_ERROR "no Gappa script ${script}")
endif()
gappa_read_power_of_two("${header}" "${CONSTANT}" exponent)
math(EXPR half "${exponent} - 1")

gappa_run("${script}" "EPS=1b${exponent}" rc log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "Gappa does not prove ${CONSTANT} = 2^${exponent} (${script}):\n${log}")
endif()
set(minimality_script "${script}")
if(DEFINED MINIMALITY_NAME)
  set(minimality_script "${source_dir}/proofs/gappa/${MINIMALITY_NAME}.g")
endif()
gappa_run("${minimality_script}" "EPS=1b${half}" rc log)
if(rc EQUAL 0)
  message(FATAL_ERROR "${CONSTANT} = 2^${exponent} is proven but not the least proven power of "
                      "two: 2^${half} is proven too (${script}). Put the least one into ${header}.")
endif()
if(NOT log MATCHES "some properties were not satisfied")
  message(FATAL_ERROR "Gappa failed unexpectedly on 2^${half}:\n${log}")
endif()
message(STATUS "${CONSTANT} = 2^${exponent} is the least power of two proven by ${script}")
