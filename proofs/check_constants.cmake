# SPDX-License-Identifier: MIT
# Checks one stage-A filter constant of predicates/filter_constants.hpp against its Gappa proof
# proofs/gappa/<pred>_filter.g; the argument is written up in proofs/invariants/filters.md.
#
#   cmake -DPRED=<orient2d|orient3d|incircle|insphere|in_ellipse> [-DGAPPA=<gappa>] [-DMODE=check|bound]
#         [-DOUT_DIR=<dir>] -P proofs/check_constants.cmake
#
# MODE=check (default; the CTest test proofs.<pred>_filter):
#   1. reads <pred>_filter_eps, _min and _max from the header (the single source of truth);
#   2. checks the range conditions of filters.md: min = 2^-L and max = 2^M are powers of two,
#      the eps product stays between 2^-1022 and 2^1023;
#   3. substitutes E, the underflow unit 2^(-1074 + d L) and the overflow bound 2^(1023 - d M)
#      into the script and requires Gappa to prove |det - Det| <= E and that every computed
#      value stays below the overflow bound (normalised units);
#   4. substitutes the next double below E and requires Gappa to fail, so the header holds the
#      least double this proof certifies, not merely some larger proven value.
# MODE=bound: prints the best bound the script proves, rounded up to a double; after a change
# of a filter's code or of its min, put that value into the header.
cmake_minimum_required(VERSION 3.25)

include("${CMAKE_CURRENT_LIST_DIR}/gappa_common.cmake")
set(header "${source_dir}/predicates/filter_constants.hpp")
if(NOT DEFINED MODE)
  set(MODE check)
endif()

# Degree of each determinant in the coordinates.
set(degree_orient2d 2)
set(degree_orient3d 3)
set(degree_incircle 4)
set(degree_insphere 5)
# in_ellipse: 4 in the differences and 1 in the metric, both normalised by their own power of
# two and bounded by the same min and max (proofs/gappa/in_ellipse_filter.g).
set(degree_in_ellipse 5)
if(NOT DEFINED degree_${PRED})
  message(FATAL_ERROR "PRED must be orient2d, orient3d, incircle, insphere or in_ellipse, not '${PRED}'")
endif()
set(d ${degree_${PRED}})
set(script "${source_dir}/proofs/gappa/${PRED}_filter.g")

# Splits a normalised hex-float literal 0x1.hhhp±e into the 53-bit integer significand and the
# exponent of its last bit: value = significand * 2^exponent.
function(parse_hexfloat literal out_significand out_exponent)
  if(NOT literal MATCHES "^0x1(\\.([0-9a-fA-F]*))?[pP]([+-]?[0-9]+)$")
    message(FATAL_ERROR "'${literal}' is not a normalised hex-float literal 0x1.hhhp±e")
  endif()
  set(fraction "${CMAKE_MATCH_2}")
  set(exponent "${CMAKE_MATCH_3}")
  string(LENGTH "${fraction}" digits)
  if(digits GREATER 13)
    message(FATAL_ERROR "'${literal}' has more than 52 fraction bits: not exactly a double")
  endif()
  while(digits LESS 13)
    string(APPEND fraction "0")
    math(EXPR digits "${digits} + 1")
  endwhile()
  math(EXPR significand "0x1${fraction}" OUTPUT_FORMAT DECIMAL)
  math(EXPR exponent "${exponent} - 52")
  set(${out_significand} ${significand} PARENT_SCOPE)
  set(${out_exponent} ${exponent} PARENT_SCOPE)
endfunction()

# Runs the script with its goal |det - Det| <= @EPS@ replaced by `goal_text` and its placeholders
# filled in, through gappa_run (which also fails on a rewriting hint that is not an identity).
function(run_gappa eps_text goal_text out_rc out_log)
  file(READ "${script}" text)
  string(REPLACE "|det - Det| <= @EPS@" "${goal_text}" text "${text}")
  set(goal_script "${OUT_DIR}/${PRED}_filter.g")
  file(WRITE "${goal_script}" "${text}")
  gappa_run("${goal_script}" "EPS=${eps_text};UNDERFLOW=${underflow};OVERFLOW=${overflow}" rc log)
  set(${out_rc} ${rc} PARENT_SCOPE)
  set(${out_log} "${log}" PARENT_SCOPE)
endfunction()

gappa_read_constant("${header}" ${PRED}_filter_eps "([0-9a-zA-Z.+-]+)" eps_literal)
gappa_read_constant("${header}" ${PRED}_filter_min "([0-9a-zA-Z.+-]+)" min_literal)
gappa_read_constant("${header}" ${PRED}_filter_max "([0-9a-zA-Z.+-]+)" max_literal)
parse_hexfloat("${eps_literal}" eps_significand eps_exponent)
parse_hexfloat("${min_literal}" min_significand min_exponent)
parse_hexfloat("${max_literal}" max_significand max_exponent)

# min = 2^-L and max = 2^M: the normalisation takes a power of two no smaller than min, and
# the underflow unit below is exact.
if(NOT min_significand EQUAL 4503599627370496 OR NOT max_significand EQUAL 4503599627370496)
  message(FATAL_ERROR "${PRED}_filter_min and _max must be powers of two (0x1p±e)")
endif()
math(EXPR L "-(${min_exponent} + 52)")
math(EXPR M "${max_exponent} + 52")
if(L LESS 0 OR M LESS 0)
  message(FATAL_ERROR "${PRED}_filter_min must be <= 1 and ${PRED}_filter_max >= 1")
endif()

# Products underflow at 2^-1074 at real scale, at most 2^(-1074 + d L) in normalised units.
math(EXPR underflow_exponent "-1074 + ${d} * ${L}")
set(underflow "1b${underflow_exponent}")

# A computed value of degree j <= d is at most 2^(d M) times larger at real scale than in
# normalised units; Gappa proves each below 2^(1023 - d M) there.
math(EXPR overflow_exponent "1023 - ${d} * ${M}")
set(overflow "1b${overflow_exponent}")

# eps >= E * 2^(d k) needs E * min^d normal: fl(E * maxx) then never rounds below E * 2^kx.
math(EXPR eps_log2 "${eps_exponent} + 52")   # E in [2^eps_log2, 2^(eps_log2 + 1))
math(EXPR smallest_eps_log2 "${eps_log2} - ${d} * ${L}")
if(smallest_eps_log2 LESS -1022)
  message(FATAL_ERROR "${PRED}: ${PRED}_filter_eps * ${PRED}_filter_min^${d} is below 2^-1022; "
                      "raise ${PRED}_filter_min")
endif()
# The eps product is below 2^(eps_log2 + 1 + d (M + 1)).
math(EXPR largest_eps_log2 "${eps_log2} + 1 + ${d} * (${M} + 1)")
if(largest_eps_log2 GREATER 1023)
  message(FATAL_ERROR "${PRED}: the eps product may overflow below ${PRED}_filter_max; lower it")
endif()

if(MODE STREQUAL "bound")
  run_gappa("" "float<53,up>(|det - Det|) in ?" rc log)
  if(NOT rc EQUAL 0 OR NOT log MATCHES "in \\[0, ([0-9]+)b(-?[0-9]+) ")
    message(FATAL_ERROR "gappa failed:\n${log}")
  endif()
  set(significand ${CMAKE_MATCH_1})
  set(exponent ${CMAKE_MATCH_2})
  while(significand LESS 4503599627370496)
    math(EXPR significand "${significand} * 2")
    math(EXPR exponent "${exponent} - 1")
  endwhile()
  math(EXPR fraction "${significand} - 4503599627370496" OUTPUT_FORMAT HEXADECIMAL)
  string(REGEX REPLACE "^0x" "" fraction "${fraction}")
  string(LENGTH "${fraction}" digits)
  while(digits LESS 13)
    string(PREPEND fraction "0")
    math(EXPR digits "${digits} + 1")
  endwhile()
  string(REGEX REPLACE "0+$" "" fraction "${fraction}")
  math(EXPR exponent "${exponent} + 52")
  if(fraction STREQUAL "")
    set(best "0x1p${exponent}")
  else()
    set(best "0x1.${fraction}p${exponent}")
  endif()
  message("${log}")
  message("Least double proven for ${PRED}_filter_eps (min = ${min_literal}): ${best}")
  message("Header value: ${eps_literal}")
  return()
elseif(NOT MODE STREQUAL "check")
  message(FATAL_ERROR "MODE must be check or bound, not '${MODE}'")
endif()

# The header value must be proven ...
run_gappa("${eps_literal}" "|det - Det| <= @EPS@" rc log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "Gappa does not prove ${PRED}_filter_eps = ${eps_literal}, or no "
                      "overflow below ${max_literal} (${script}, underflow unit ${underflow}, "
                      "overflow bound ${overflow}):\n${log}\n"
                      "Run: cmake -DPRED=${PRED} -DMODE=bound -P ${CMAKE_CURRENT_LIST_FILE}")
endif()
# ... and the next double below it must not be.
if(eps_significand EQUAL 4503599627370496)
  math(EXPR below_significand "2 * ${eps_significand} - 1")
  math(EXPR below_exponent "${eps_exponent} - 1")
else()
  math(EXPR below_significand "${eps_significand} - 1")
  set(below_exponent ${eps_exponent})
endif()
set(below "${below_significand}b${below_exponent}")
run_gappa("${below}" "|det - Det| <= @EPS@" rc log)
gappa_expect_unproven(${rc} "${log}" "${below}"
  "${PRED}_filter_eps = ${eps_literal} is proven but not the least proven double: ${below} is \
proven too. Put the least one into ${header}; run: cmake -DPRED=${PRED} -DMODE=bound -P \
${CMAKE_CURRENT_LIST_FILE}")
message(STATUS "${PRED}_filter_eps = ${eps_literal} is the least double proven by ${script} "
               "(min ${min_literal}: underflow unit ${underflow}; max ${max_literal}: "
               "overflow bound ${overflow})")
