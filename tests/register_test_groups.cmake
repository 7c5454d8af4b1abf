# Run after a test executable is built (cmake -P): lists its tests and writes one ctest entry per
# group of at most GROUP_SIZE tests of a suite, each group run in one process. Starting a test
# process costs 0.4 s (ITK, GDCM and OpenImageIO load) and 0.8 s under AddressSanitizer, which
# one process per test (gtest_discover_tests) paid some 1500 times per CI run.
#
# Variables: EXECUTABLE, MODULE, OUTPUT (the ctest file to write), GROUP_SIZE, SKIPPED_SUITES
# (run by entries of their own; ','-separated suite names), SINGLE_TESTS (','-separated Suite.Test
# names that get an entry of their own, so a run can leave them out with ctest -E).
cmake_minimum_required(VERSION 3.25)
string(REPLACE "," ";" SKIPPED_SUITES "${SKIPPED_SUITES}")
string(REPLACE "," ";" SINGLE_TESTS "${SINGLE_TESTS}")

execute_process(COMMAND "${EXECUTABLE}" --gtest_list_tests
                OUTPUT_VARIABLE listing RESULT_VARIABLE status TIMEOUT 60)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} --gtest_list_tests failed (${status})")
endif()

string(REPLACE ";" "\\;" listing "${listing}")
string(REPLACE "\n" ";" lines "${listing}")
set(suites "")
foreach(line IN LISTS lines)
  string(REGEX REPLACE " *#.*$" "" line "${line}")  # "  # GetParam() = ..." comments
  if(line MATCHES "^([^ ]+)\\.$")
    set(suite "${CMAKE_MATCH_1}")
    list(APPEND suites "${suite}")
    set(cases_${suite} "")
  elseif(line MATCHES "^  ([^ ]+)$")
    list(APPEND cases_${suite} "${suite}.${CMAKE_MATCH_1}")
  endif()
endforeach()

set(script "")
macro(add_group name filter)
  string(APPEND script "add_test([=[${MODULE}_tests.${name}]=] [=[${EXECUTABLE}]=] [=[--gtest_filter=${filter}]=])\n")
endmacro()

foreach(suite IN LISTS suites)
  if(suite IN_LIST SKIPPED_SUITES)
    continue()
  endif()
  set(grouped "")
  foreach(test IN LISTS cases_${suite})
    if(test IN_LIST SINGLE_TESTS)
      add_group("${test}" "${test}")
    else()
      list(APPEND grouped "${test}")
    endif()
  endforeach()
  list(LENGTH grouped count)
  if(count EQUAL 0)
    continue()
  endif()
  # Groups of near-equal size: 40 tests in groups of at most 16 are 14 + 13 + 13.
  math(EXPR group_count "(${count} + ${GROUP_SIZE} - 1) / ${GROUP_SIZE}")
  set(first 0)
  foreach(group RANGE 1 ${group_count})
    math(EXPR last "${count} * ${group} / ${group_count}")
    math(EXPR length "${last} - ${first}")
    list(SUBLIST grouped ${first} ${length} members)
    list(JOIN members ":" filter)
    if(group_count EQUAL 1)
      add_group("${suite}" "${filter}")
    else()
      add_group("${suite}#${group}" "${filter}")
    endif()
    set(first ${last})
  endforeach()
endforeach()
file(WRITE "${OUTPUT}" "${script}")
