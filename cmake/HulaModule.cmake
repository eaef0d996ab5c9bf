# SPDX-License-Identifier: MIT
# One-line declarations for modules, tests and benchmarks.
#
#   hula_add_module(nurbs SOURCES a.cpp b.cpp DEPS hula::core)
#   hula_add_test(nurbs_knot_vector SOURCES knot_vector_test.cpp DEPS hula::nurbs LABELS unit)
#   hula_test_groups(nurbs)   # at the top of a tests/ directory: one program per label (below)
#   hula_add_bench(nurbs_eval SOURCES evaluate_bench.cpp DEPS hula::nurbs)
#
# Modules other than `testing` are installed and exported as HulaHoops::<name>.
#
# The DEPS list of a module *is* the layering of DESIGN.md: a module may only
# depend on modules below it, and hula_add_module refuses an upward edge.

set(HULA_MODULE_ORDER core nurbs law curve diffgeom intrinsic optim studies io io_studies oli_store oli_kernel oli_exchange oli server testing)

# Unity batches for `target` when HULA_UNITY_BUILD is on (CMakeLists.txt): HULA_UNITY_BATCH_SIZE files per
# translation unit, in their SOURCES order. CMake keeps a source with its own COMPILE_OPTIONS or
# COMPILE_DEFINITIONS (the SIMD variants of hula_simd_sources) out of the batches by itself; a file
# that must stay out for another reason gets SKIP_UNITY_BUILD_INCLUDE with a comment saying why.
function(hula_unity_build target)
  if(HULA_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${HULA_UNITY_BATCH_SIZE})
    # GCC warns when a class of an included file has a member of an anonymous-namespace type (an ODR
    # hazard in a header); in a unity batch every source is an included file, so the pimpl structs
    # holding their file's private types would be reported. The sources are still compiled alone in
    # the `dev` preset, where the warning keeps its meaning.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
      target_compile_options(${target} PRIVATE -Wno-subobject-linkage)
    endif()
  endif()
endfunction()

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
  hula_unity_build(hula_${name})
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

# Test binaries. Each hula_add_test is one gtest program test_<name>, unless its directory called
# hula_test_groups(<group>) first: then the tests of that directory are compiled into one program per
# label, test_<group>_<label>, from all their sources (unity batches with HULA_UNITY_BUILD, so gtest,
# RapidCheck and the hula headers are parsed once per batch, not once per test file). ctest runs every
# gtest test in a process of its own either way (gtest_discover_tests), so the test names, labels,
# environment and working directory are those of separate programs. A test whose program is named
# elsewhere (compile definitions, add_dependencies, include directories) or that changes its process
# (a replaced global operator new, signal handlers) passes OWN_BINARY and keeps test_<name>.
function(hula_add_test name)
  cmake_parse_arguments(ARG "OWN_BINARY" "" "SOURCES;DEPS;LABELS" ${ARGN})
  if(NOT ARG_LABELS)
    set(ARG_LABELS unit)
  endif()
  list(LENGTH ARG_LABELS label_count)
  if(label_count GREATER 1)
    # gtest_discover_tests flattens lists: one label per test binary.
    message(FATAL_ERROR "hula_add_test(${name}): give one label per test binary, got '${ARG_LABELS}'")
  endif()
  if(HULA_TEST_GROUP AND NOT ARG_OWN_BINARY)
    set(group ${HULA_TEST_GROUP}_${ARG_LABELS})
    list(TRANSFORM ARG_SOURCES PREPEND ${CMAKE_CURRENT_SOURCE_DIR}/ REGEX "^[^/]")
    set_property(DIRECTORY APPEND PROPERTY HULA_TEST_GROUPS ${group})
    set_property(DIRECTORY APPEND PROPERTY HULA_TEST_GROUP_${group}_SOURCES ${ARG_SOURCES})
    set_property(DIRECTORY APPEND PROPERTY HULA_TEST_GROUP_${group}_DEPS ${ARG_DEPS})
    set_property(DIRECTORY PROPERTY HULA_TEST_GROUP_${group}_LABEL ${ARG_LABELS})
    return()
  endif()
  hula_test_program(test_${name} "${ARG_SOURCES}" "${ARG_DEPS}" ${ARG_LABELS})
endfunction()

function(hula_test_program target sources deps label)
  add_executable(${target} ${sources})
  target_link_libraries(${target} PRIVATE ${deps} hula_test_main GTest::gtest GTest::gmock
    rapidcheck rapidcheck_gtest hula::warnings hula::sanitize)
  gtest_discover_tests(${target}
    DISCOVERY_MODE PRE_TEST
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    PROPERTIES LABELS "${label}"
    ENVIRONMENT "HULA_TEST_DATA=${PROJECT_SOURCE_DIR}/tests/data")
endfunction()

# Called at the top of a tests/ directory: its hula_add_test calls are grouped into test_<group>_<label>
# programs, made when the directory's CMakeLists.txt has been read.
function(hula_test_groups group)
  set(HULA_TEST_GROUP ${group} PARENT_SCOPE)
  cmake_language(DEFER CALL hula_make_test_groups)
endfunction()

function(hula_make_test_groups)
  get_property(groups DIRECTORY PROPERTY HULA_TEST_GROUPS)
  list(REMOVE_DUPLICATES groups)
  foreach(group IN LISTS groups)
    get_property(sources DIRECTORY PROPERTY HULA_TEST_GROUP_${group}_SOURCES)
    get_property(deps DIRECTORY PROPERTY HULA_TEST_GROUP_${group}_DEPS)
    get_property(label DIRECTORY PROPERTY HULA_TEST_GROUP_${group}_LABEL)
    list(REMOVE_DUPLICATES deps)
    hula_test_program(test_${group} "${sources}" "${deps}" ${label})
    hula_unity_build(test_${group})
  endforeach()
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
