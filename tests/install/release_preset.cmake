# SPDX-License-Identifier: MIT
# The release preset (scripts/run.sh) builds the Python package and MPI islands when their Debian
# packages are present and says so in its configure output; without them (find_package disabled, as on
# a machine without python3-dev/pybind11-dev or libopenmpi-dev) it configures and says they are not
# built. Configure only, in scratch build directories (without Open CASCADE, to keep it short).
#   cmake -DSOURCE_DIR=... -DWORK_DIR=... -P release_preset.cmake
cmake_minimum_required(VERSION 3.25)  # policies of script mode (IN_LIST)
foreach(var SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "release_preset.cmake needs -D${var}=...")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})

function(configure dir expect_python expect_mpi)
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} --preset release -B ${WORK_DIR}/${dir}
                          -DHULA_WITH_OCCT=OFF ${ARGN}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cmake --preset release ${ARGN} failed (${rc}):\n${out}\n${err}")
  endif()
  foreach(line "-- HulaHoops: Python package hulahoops: ${expect_python}"
               "-- HulaHoops: MPI islands: ${expect_mpi}")
    string(FIND "${out}" "${line}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "cmake --preset release ${ARGN}: no line '${line}' in\n${out}")
    endif()
  endforeach()
  file(STRINGS ${WORK_DIR}/${dir}/CMakeCache.txt cache REGEX "^(HULA_PYTHON|HULA_MPI):")
  message(STATUS "release preset ${ARGN}: Python ${expect_python}, MPI ${expect_mpi} (cache: ${cache})")
endfunction()

configure(with "built (" "built (")
configure(without "not built (HULA_PYTHON=AUTO" "not built (HULA_MPI=AUTO"
          -DCMAKE_DISABLE_FIND_PACKAGE_pybind11=ON -DCMAKE_DISABLE_FIND_PACKAGE_MPI=ON)
