# SPDX-License-Identifier: MIT
# One-line declarations for modules, tests and benchmarks.
#
#   hula_add_module(nurbs SOURCES a.cpp b.cpp DEPS hula::core)
#   hula_add_test(nurbs_knot_vector SOURCES knot_vector_test.cpp DEPS hula::nurbs LABELS unit)
#   hula_add_bench(nurbs_eval SOURCES evaluate_bench.cpp DEPS hula::nurbs)
#
# The DEPS list of a module *is* the layering of DESIGN.md: a module may only
# depend on modules below it, and hula_add_module refuses an upward edge.

set(HULA_MODULE_ORDER core nurbs law curve diffgeom intrinsic optim studies io oli_store oli_kernel oli_exchange oli server testing)

function(hula_add_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PUBLIC_LIBS;PRIVATE_LIBS" ${ARGN})
  list(FIND HULA_MODULE_ORDER ${name} self_rank)
  foreach(dep IN LISTS ARG_DEPS)
    string(REPLACE "hula::" "" dep_name ${dep})
    list(FIND HULA_MODULE_ORDER ${dep_name} dep_rank)
    if(dep_rank GREATER_EQUAL self_rank AND NOT name STREQUAL "testing")
      message(FATAL_ERROR "hula module '${name}' may not depend on '${dep_name}' (upward dependency)")
    endif()
  endforeach()
  add_library(hula_${name} ${ARG_SOURCES})
  add_library(hula::${name} ALIAS hula_${name})
  target_include_directories(hula_${name} PUBLIC ${PROJECT_SOURCE_DIR}/src)
  target_compile_features(hula_${name} PUBLIC cxx_std_20)
  target_link_libraries(hula_${name}
    PUBLIC ${ARG_DEPS} ${ARG_PUBLIC_LIBS}
    PRIVATE hula::warnings hula::sanitize ${ARG_PRIVATE_LIBS})
  set_target_properties(hula_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()

function(hula_add_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;LABELS" ${ARGN})
  add_executable(test_${name} ${ARG_SOURCES})
  target_link_libraries(test_${name} PRIVATE ${ARG_DEPS} hula_test_main GTest::gtest GTest::gmock
    rapidcheck rapidcheck_gtest hula::warnings hula::sanitize)
  if(NOT ARG_LABELS)
    set(ARG_LABELS unit)
  endif()
  list(LENGTH ARG_LABELS label_count)
  if(label_count GREATER 1)
    # gtest_discover_tests flattens lists: one label per test binary.
    message(FATAL_ERROR "hula_add_test(${name}): give one label per test binary, got '${ARG_LABELS}'")
  endif()
  gtest_discover_tests(test_${name}
    DISCOVERY_MODE PRE_TEST
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    PROPERTIES LABELS "${ARG_LABELS}"
    ENVIRONMENT "HULA_TEST_DATA=${PROJECT_SOURCE_DIR}/tests/data")
endfunction()

function(hula_add_bench name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(bench_${name} ${ARG_SOURCES})
  target_link_libraries(bench_${name} PRIVATE ${ARG_DEPS} benchmark::benchmark benchmark::benchmark_main
    hula::warnings)
endfunction()
