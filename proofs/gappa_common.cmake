# SPDX-License-Identifier: MIT
# What the check_*_constants.cmake scripts share: locating Gappa and the sources, reading a
# constant from a header, and running a Gappa script with its placeholders filled in.
# Included by those scripts (cmake -P); sets source_dir, GAPPA and OUT_DIR.
cmake_path(GET CMAKE_CURRENT_LIST_DIR PARENT_PATH source_dir)
if(NOT DEFINED GAPPA)
  find_program(GAPPA gappa REQUIRED)
endif()
if(NOT DEFINED OUT_DIR)
  set(OUT_DIR "${CMAKE_CURRENT_BINARY_DIR}")
endif()

# The one line `inline constexpr [long ]double <constant> = ...;` of `header`, matched against
# `pattern` (a regex after "<constant> = "); CMAKE_MATCH_1 of it is returned in `out`.
function(gappa_read_constant header constant pattern out)
  file(STRINGS "${header}" lines REGEX "inline constexpr (long )?double ${constant} = [^;]+;")
  list(LENGTH lines count)
  if(NOT count EQUAL 1)
    message(FATAL_ERROR "${header}: expected exactly one definition of ${constant}, found ${count}")
  endif()
  if(NOT lines MATCHES "${constant} = ${pattern}")
    message(FATAL_ERROR "${header}: ${constant} is not written as ${pattern}")
  endif()
  set(${out} "${CMAKE_MATCH_1}" PARENT_SCOPE)
endfunction()

# The exponent e of a constant written 0x1p±e (a power of two: multiplying by it is exact).
function(gappa_read_power_of_two header constant out)
  gappa_read_constant("${header}" "${constant}" "0x1p([+-]?[0-9]+)L?[^0-9]" e)
  math(EXPR e "${e}")
  set(${out} ${e} PARENT_SCOPE)
endfunction()

# After a gappa_run with a smaller constant `tried`: fails with `not_least` when Gappa proved it
# (the header's constant is not the least), and on any failure other than an unproven goal (a
# syntax error or a crash must not pass for "not proven").
function(gappa_expect_unproven rc log tried not_least)
  if(rc EQUAL 0)
    message(FATAL_ERROR "${not_least}")
  endif()
  if(NOT log MATCHES "some properties were not satisfied")
    message(FATAL_ERROR "Gappa failed unexpectedly on ${tried}:\n${log}")
  endif()
endfunction()

# Runs Gappa on `script` with each "@KEY@" replaced as the list `substitutions` says
# (KEY=value entries); an unknown placeholder, or a rewriting hint that is not an identity
# (which Gappa would only warn about, then use unchecked), is a fatal error.
function(gappa_run script substitutions out_rc out_log)
  file(READ "${script}" text)
  foreach(entry IN LISTS substitutions)
    string(REGEX MATCH "^([A-Z_]+)=(.*)$" _ "${entry}")
    string(REPLACE "@${CMAKE_MATCH_1}@" "${CMAKE_MATCH_2}" text "${text}")
  endforeach()
  if(text MATCHES "@[A-Z_]+@")
    message(FATAL_ERROR "${script}: unknown placeholder ${CMAKE_MATCH_0}")
  endif()
  cmake_path(GET script STEM stem)
  set(instance "${OUT_DIR}/${stem}.instance.g")
  file(WRITE "${instance}" "${text}")
  execute_process(COMMAND "${GAPPA}" "${instance}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(err MATCHES "not trivially equal")
    message(FATAL_ERROR "${script}: a rewriting hint is not an identity:\n${err}")
  endif()
  set(${out_rc} ${rc} PARENT_SCOPE)
  set(${out_log} "${instance}:\n${err}${out}" PARENT_SCOPE)
endfunction()
