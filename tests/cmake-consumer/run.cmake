# SPDX-License-Identifier: MIT
# ctest driver of the consumer test: installs the build tree into a fresh prefix, configures, builds and
# runs tests/cmake-consumer against it with find_package(HulaHoops) — one program per exported target,
# and every target the installed HulaHoopsTargets.cmake declares must have one — then compiles and runs
# the same programs with the flags of hulahoops.pc (pkg-config) instead.
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DCXX=... [-DWITH_OCCT=ON] [-DWITH_MPI=ON] -P run.cmake
cmake_minimum_required(VERSION 3.25)  # policies of script mode (IN_LIST)
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR CXX)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run.cmake needs -D${var}=...")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
set(scratch ${WORK_DIR}/scratch)
file(MAKE_DIRECTORY ${scratch})

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
endfunction()

run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(f include/hula/version.hpp include/hula/nurbs/nurbs_curve.hpp lib/cmake/HulaHoops/HulaHoopsConfig.cmake
          lib/cmake/HulaHoops/HulaHoopsConfigVersion.cmake lib/pkgconfig/hulahoops.pc)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "the install tree lacks ${f}")
  endif()
endforeach()

# The plugins (hula/core/plugin.hpp) are installed beside the libraries, and the installed `hula` loads
# them from there (bin/../lib/hulahoops), not from the build tree.
set(plugins pagmo ceres)
if(WITH_OCCT)
  list(APPEND plugins occt)
endif()
if(WITH_MPI)
  list(APPEND plugins mpi)
endif()
foreach(p IN LISTS plugins)
  if(NOT EXISTS ${prefix}/lib/hulahoops/libhula_${p}.so)
    message(FATAL_ERROR "the install tree lacks lib/hulahoops/libhula_${p}.so")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E env LD_DEBUG=files ${prefix}/bin/hula optimise --problem sphere
    --dimension 2 --algorithm pagmo-de --population 8 --generations 2 --seed 1
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(FIND "${err}" "file=${prefix}/bin/../lib/hulahoops/libhula_pagmo.so" at)
if(NOT rc EQUAL 0 OR at EQUAL -1)
  message(FATAL_ERROR "the installed hula did not run pagmo-de with the installed plugin (${rc}):\n${out}\n${err}")
endif()

# find_package route: each program links its one target.
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/cmake-consumer -B ${WORK_DIR}/build -G Ninja
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_BUILD_TYPE=Release)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build --parallel 2)

# Every exported target has its program (a new module without one fails here).
file(READ ${prefix}/lib/cmake/HulaHoops/HulaHoopsTargets.cmake exported_text)
string(REGEX MATCHALL "add_library\\(HulaHoops::[a-z_]+" exported "${exported_text}")
list(TRANSFORM exported REPLACE "add_library\\(HulaHoops::" "")
file(READ ${WORK_DIR}/build/consumer-targets.txt programs)
list(LENGTH exported exported_count)
foreach(t IN LISTS exported)
  if(NOT t IN_LIST programs)
    message(FATAL_ERROR "HulaHoops::${t} is exported but tests/cmake-consumer has no ${t}.cpp linking it")
  endif()
endforeach()
if(exported_count LESS 15)
  message(FATAL_ERROR "only ${exported_count} exported targets found: ${exported}")
endif()
# A program of the consumer's own is not in the install tree: it is told where the installed plugins are
# (HULA_PLUGIN_DIR, hula/core/plugin.hpp), so that studies (Ceres) and optim_pagmo run with those, not
# with the build tree's.
foreach(t IN LISTS programs)
  run(${CMAKE_COMMAND} -E env HULA_PLUGIN_DIR=${prefix}/lib/hulahoops ${WORK_DIR}/build/consumer_${t} ${prefix}
      ${scratch})
endforeach()
message(STATUS "find_package(HulaHoops): ${exported_count} exported targets, each linked alone and run")

# pkg-config route (the .pc finds its prefix from its own directory: relocatable): the same programs
# with `pkg-config --cflags --libs hulahoops` only.
find_program(PKG_CONFIG pkg-config REQUIRED)
set(ENV{PKG_CONFIG_PATH} ${prefix}/lib/pkgconfig)
execute_process(COMMAND ${PKG_CONFIG} --cflags --libs hulahoops
  RESULT_VARIABLE rc OUTPUT_VARIABLE flags OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pkg-config does not know hulahoops")
endif()
message(STATUS "pkg-config --cflags --libs hulahoops: ${flags}")
separate_arguments(flags UNIX_COMMAND "${flags}")
foreach(t IN LISTS programs)
  run(${CXX} ${SOURCE_DIR}/tests/cmake-consumer/${t}.cpp -o ${WORK_DIR}/pc-${t} ${flags})
  run(${CMAKE_COMMAND} -E env HULA_PLUGIN_DIR=${prefix}/lib/hulahoops ${WORK_DIR}/pc-${t} ${prefix} ${scratch})
endforeach()
