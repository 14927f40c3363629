# SPDX-License-Identifier: MIT
# Checks one relative-filter constant of predicates/filter_constants.hpp against its Gappa proof
# proofs/gappa/<name>.g; the model is written up in proofs/invariants/filters.md ("Relative
# filters").
#
#   cmake -DNAME=<proof name> -DCONSTANT=<constant> [-DMINIMALITY_NAME=<script>]
#         [-DMAX_ROUNDINGS=<constant>] [-DROUNDINGS=<constant>[,<constant>...]]
#         [-DGAPPA=<gappa>] [-DOUT_DIR=<dir>]
#         -P proofs/check_relative_constants.cmake
#
# 1. reads CONSTANT from the header (the single source of truth); it must be a power of two
#    0x1p±e (so that multiplying a bound by it is exact);
# 2. substitutes it for @EPS@ in the script and requires Gappa to prove the script's goal;
# 3. substitutes half of it and requires Gappa to fail, so the header holds the least power of
#    two this model certifies, not merely some larger proven value (on MINIMALITY_NAME.g when
#    given: a subset of the goals on which Gappa fails fast).
# 4. with MAX_ROUNDINGS (a filter that counts its roundings k, u = 2^-64, and abstains above the
#    header's `inline constexpr int <MAX_ROUNDINGS> = n;`): requires the script to state both
#    goals of every k = 1..n, so that a larger n in the header without a proof of it fails.
# 5. with ROUNDINGS (filters whose terms carry their rounding count in the type, u = 2^-53,
#    predicates/relative_filter.hpp): for each header constant `inline constexpr int <c> = n;`
#    the script must state both goals for n factors, so that a count the code is certified
#    with is a count Gappa proves.
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
gappa_expect_unproven(${rc} "${log}" "2^${half}"
  "${CONSTANT} = 2^${exponent} is proven but not the least proven power of two: 2^${half} is \
proven too (${script}). Put the least one into ${header}.")
if(DEFINED MAX_ROUNDINGS)
  file(STRINGS "${header}" lines REGEX "inline constexpr int ${MAX_ROUNDINGS} = [0-9]+;")
  list(LENGTH lines count)
  if(NOT count EQUAL 1 OR NOT lines MATCHES "${MAX_ROUNDINGS} = ([0-9]+)")
    message(FATAL_ERROR "${header}: expected one definition `inline constexpr int "
                        "${MAX_ROUNDINGS} = <n>;`, found ${count}")
  endif()
  set(max_roundings ${CMAKE_MATCH_1})
  file(READ "${script}" text)
  foreach(k RANGE 1 ${max_roundings})
    math(EXPR kb "${k} + 1")
    string(FIND "${text}" "value${k} - 1 - @EPS@ * ${kb} * 1b-64 * bound${kb} <= 0" above)
    string(FIND "${text}" "1 - value${k} - @EPS@ * ${kb} * 1b-64 * bound${kb} <= 0" below)
    if(above EQUAL -1 OR below EQUAL -1)
      message(FATAL_ERROR "${MAX_ROUNDINGS} = ${max_roundings} but ${script} proves no goal for "
                          "k = ${k} roundings")
    endif()
  endforeach()
endif()
if(DEFINED ROUNDINGS)
  string(REPLACE "," ";" rounding_constants "${ROUNDINGS}")
  file(READ "${script}" text)
  foreach(constant_name IN LISTS rounding_constants)
    file(STRINGS "${header}" lines REGEX "inline constexpr int ${constant_name} = [0-9]+;")
    list(LENGTH lines count)
    if(NOT count EQUAL 1 OR NOT lines MATCHES "${constant_name} = ([0-9]+)")
      message(FATAL_ERROR "${header}: expected one definition `inline constexpr int "
                          "${constant_name} = <n>;`, found ${count}")
    endif()
    set(n ${CMAKE_MATCH_1})
    string(FIND "${text}" "value${n} - 1 - @EPS@ * bound${n} <= 0" above)
    string(FIND "${text}" "1 - value${n} - @EPS@ * bound${n} <= 0" below)
    if(above EQUAL -1 OR below EQUAL -1)
      message(FATAL_ERROR "${constant_name} = ${n} but ${script} proves no goal for ${n} roundings")
    endif()
  endforeach()
endif()
message(STATUS "${CONSTANT} = 2^${exponent} is the least power of two proven by ${script}")
