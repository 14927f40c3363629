# SPDX-License-Identifier: MIT
# Checks the three constants of triangle_area_sign's stage A (predicates/filter_constants.hpp:
# triangle_area_filter_eps, _result_eps, _floor) against proofs/gappa/triangle_area_filter.g; the
# model and the hand steps are in proofs/invariants/filters.md ("triangle_area_sign").
#
#   cmake [-DGAPPA=<gappa>] [-DOUT_DIR=<dir>] -P proofs/check_triangle_area_constants.cmake
#
# 1. reads the three constants from the header; each must be a power of two written 0x1p±e;
# 2. requires Gappa to prove the script with them, with no warning that the rewriting is not an
#    identity;
# 3. requires Gappa to fail with eps / 2 and with result_eps / 2 (each is the least power of two
#    this model allows). floor is only required to be proven: a smaller one is proven too, and
#    the header keeps 2^-1060 so that every decision stays the same.
cmake_minimum_required(VERSION 3.25)

include("${CMAKE_CURRENT_LIST_DIR}/gappa_common.cmake")
set(header "${source_dir}/predicates/filter_constants.hpp")
set(script "${source_dir}/proofs/gappa/triangle_area_filter.g")
gappa_read_power_of_two("${header}" triangle_area_filter_eps product)
gappa_read_power_of_two("${header}" triangle_area_filter_result_eps result)
gappa_read_power_of_two("${header}" triangle_area_filter_floor floor)

# The three constants as the script's placeholders.
function(run_gappa product result floor out_rc out_log)
  gappa_run("${script}" "PRODUCT_EPS=1b${product};RESULT_EPS=1b${result};FLOOR=1b${floor}" rc log)
  set(${out_rc} ${rc} PARENT_SCOPE)
  set(${out_log} "${log}" PARENT_SCOPE)
endfunction()

run_gappa(${product} ${result} ${floor} rc log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "Gappa does not prove the triangle_area constants 2^${product}, "
                      "2^${result}, 2^${floor} (${script}):\n${log}")
endif()
# Fails when Gappa proves the bounds with the constant `which` (product or result, named
# `name` in the header) halved too: the header must hold the least constant.
function(expect_least which name)
  set(try_product ${product})
  set(try_result ${result})
  math(EXPR try_${which} "${${which}} - 1")
  run_gappa(${try_product} ${try_result} ${floor} rc log)
  gappa_expect_unproven(${rc} "${log}" "${name} = 2^${try_${which}}"
    "${name} = 2^${${which}} is not the least: 2^${try_${which}} is proven too (${script}). \
Put the least one into ${header}.")
endfunction()

expect_least(product triangle_area_filter_eps)
expect_least(result triangle_area_filter_result_eps)
message(STATUS "triangle_area_filter constants 2^${product}, 2^${result}, 2^${floor} are proven")
