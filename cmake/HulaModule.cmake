# SPDX-License-Identifier: MIT
# One-line declarations for modules, tests and benchmarks.
#
#   hula_add_module(nurbs SOURCES a.cpp b.cpp DEPS hula::core)
#   hula_add_test(nurbs_knot_vector SOURCES knot_vector_test.cpp DEPS hula::nurbs LABELS unit)
#   hula_add_bench(nurbs_eval SOURCES evaluate_bench.cpp DEPS hula::nurbs)
#
# Modules other than `testing` are installed and exported as HulaHoops::<name>.
#
# The DEPS list of a module *is* the layering of DESIGN.md: a module may only
# depend on modules below it, and hula_add_module refuses an upward edge.

set(HULA_MODULE_ORDER core nurbs law curve diffgeom intrinsic optim studies io io_studies oli_store oli_kernel oli_exchange oli server testing)

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
  # The source tree and the generated hula/version.hpp in the build; include/ once installed.
  target_include_directories(hula_${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>
    $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(hula_${name} PUBLIC cxx_std_20)
  # Warnings and sanitizers are our build's business, not a consumer's: build interface only.
  target_link_libraries(hula_${name}
    PUBLIC ${ARG_DEPS} ${ARG_PUBLIC_LIBS}
    PRIVATE $<BUILD_INTERFACE:hula::warnings> $<BUILD_INTERFACE:hula::sanitize> ${ARG_PRIVATE_LIBS})
  set_target_properties(hula_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON EXPORT_NAME ${name})
  # Every library module is installed and exported as HulaHoops::<name> (cmake/HulaInstall.cmake);
  # the test-support library is not part of the package.
  if(NOT name STREQUAL "testing")
    install(TARGETS hula_${name} EXPORT HulaHoopsTargets
      ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
      LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
      INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
    set_property(GLOBAL APPEND PROPERTY HULA_INSTALLED_MODULES ${name})
  endif()
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

# Vectorised kernels (hula/core/simd.hpp): `base` is compiled for the portable baseline, and on x86-64
# `avx2` and `avx512` for AVX2 and AVX-512F; all three without fused multiply-add, so every variant
# gives the same doubles. Appends the sources to `out` and, on x86-64, sets HULA_SIMD_X86 in
# `<out>_DEFINES` (the dispatcher compiles stubs for the wide variants elsewhere).
function(hula_simd_sources out base avx2 avx512)
  set(sources ${base})
  set(defines "")
  if(CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64|amd64")
    list(APPEND sources ${avx2} ${avx512})
    set_source_files_properties(${avx2} PROPERTIES COMPILE_OPTIONS "-mavx2;-ffp-contract=off")
    set_source_files_properties(${avx512} PROPERTIES COMPILE_OPTIONS "-mavx512f;-ffp-contract=off")
    set(defines HULA_SIMD_X86)
  endif()
  set_property(SOURCE ${base} APPEND PROPERTY COMPILE_OPTIONS "-ffp-contract=off")
  set(${out} ${sources} PARENT_SCOPE)
  set(${out}_DEFINES ${defines} PARENT_SCOPE)
endfunction()

function(hula_add_bench name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(bench_${name} ${ARG_SOURCES})
  target_link_libraries(bench_${name} PRIVATE ${ARG_DEPS} benchmark::benchmark benchmark::benchmark_main
    hula::warnings)
  # bench/reference/: the hand-written kernels every ratio in docs/benchmarks.md is measured against.
  target_include_directories(bench_${name} PRIVATE ${PROJECT_SOURCE_DIR}/bench)
endfunction()

# Plugins (hula/core/plugin.hpp): a MODULE library libhula_<name>.so, loaded with dlopen on first use so
# that programs which never use it do not load the large library it wraps at start-up. It links its own
# copies of the static modules it needs, hidden (--exclude-libs): only its extern "C" entry points,
# marked HULA_PLUGIN_EXPORT, are visible. Built into HULA_PLUGIN_BUILD_DIR, installed into
# HULA_PLUGIN_INSTALL_DIR; `owner` (the static target whose code calls plugin_symbol) depends on it, so
# every program linking the owner has the plugin built beside it.
#
#   hula_add_plugin(pagmo OWNER hula_optim_pagmo SOURCES pagmo_plugin.cpp LIBS hula::optim Pagmo::pagmo)
set(HULA_PLUGIN_BUILD_DIR ${PROJECT_BINARY_DIR}/lib/hulahoops)
set(HULA_PLUGIN_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/hulahoops)
function(hula_add_plugin name)
  cmake_parse_arguments(ARG "" "OWNER" "SOURCES;LIBS" ${ARGN})
  add_library(hula_plugin_${name} MODULE ${ARG_SOURCES})
  target_link_libraries(hula_plugin_${name} PRIVATE ${ARG_LIBS} hula::warnings hula::sanitize)
  target_compile_definitions(hula_plugin_${name} PRIVATE
    "HULA_PLUGIN_EXPORT=extern \"C\" __attribute__((visibility(\"default\")))")
  target_link_options(hula_plugin_${name} PRIVATE -Wl,--exclude-libs,ALL -Wl,-Bsymbolic)
  # Every symbol resolved at link time, not at dlopen; not with sanitizers, whose runtime (clang's is
  # static) is found in the program only.
  if(NOT HULA_SANITIZE)
    target_link_options(hula_plugin_${name} PRIVATE -Wl,--no-undefined)
  endif()
  set_target_properties(hula_plugin_${name} PROPERTIES
    OUTPUT_NAME hula_${name} PREFIX lib
    LIBRARY_OUTPUT_DIRECTORY ${HULA_PLUGIN_BUILD_DIR}
    CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  install(TARGETS hula_plugin_${name} LIBRARY DESTINATION ${HULA_PLUGIN_INSTALL_DIR})
  add_dependencies(${ARG_OWNER} hula_plugin_${name})
endfunction()
