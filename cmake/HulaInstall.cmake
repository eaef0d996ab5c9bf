# SPDX-License-Identifier: MIT
# Installation of the libraries, after fmt's install/export:
# headers under include/hula, the module libraries exported as HulaHoops::<module>
# (hula_add_module adds each to the HulaHoopsTargets export set), the
# HulaHoopsConfig.cmake package with its version file, hulahoops.pc, and the
# generated hula/version.hpp. Included last by the top-level CMakeLists.txt.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(HULA_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/HulaHoops)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/hula/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hula
  FILES_MATCHING PATTERN "*.hpp"
  PATTERN "testing" EXCLUDE)
install(FILES ${PROJECT_BINARY_DIR}/include/hula/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hula)

install(EXPORT HulaHoopsTargets NAMESPACE HulaHoops:: DESTINATION ${HULA_CMAKE_DIR} FILE HulaHoopsTargets.cmake)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/HulaHoopsConfig.cmake.in
  ${PROJECT_BINARY_DIR}/HulaHoopsConfig.cmake INSTALL_DESTINATION ${HULA_CMAKE_DIR})
# 0.x releases break compatibility between minor versions; SameMinorVersion says so.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/HulaHoopsConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/HulaHoopsConfig.cmake ${PROJECT_BINARY_DIR}/HulaHoopsConfigVersion.cmake
  DESTINATION ${HULA_CMAKE_DIR})

# pkg-config: static libraries listed from the top layer down, so the linker resolves each
# module's references in the ones below it.
get_property(hula_installed GLOBAL PROPERTY HULA_INSTALLED_MODULES)
set(HULA_PC_LIBS "")
list(REVERSE hula_installed)
foreach(m IN LISTS hula_installed)
  string(APPEND HULA_PC_LIBS " -lhula_${m}")
endforeach()
string(STRIP "${HULA_PC_LIBS}" HULA_PC_LIBS)
# What the modules need of other packages (the libraries are static, so a private dependency is the
# consumer's too): those with a pkg-config file in Requires, the others in Libs after ours.
#   TBB (core), nlohmann_json (io), Eigen (studies), SQLite (oli_store);
#   pagmo2 with Boost.Serialization (optim_pagmo), threads (server, core); Ceres is linked by the plugin
#   libhula_ceres.so only (src/hula/studies/CMakeLists.txt), not by the modules;
#   with Open CASCADE: its headers (occt_convert.hpp), HULA_WITH_OCCT and the toolkits of HulaHoops::occt.
set(HULA_PC_REQUIRES "tbb nlohmann_json eigen3 sqlite3")
set(HULA_PC_DEP_LIBS "-lpagmo -lboost_serialization -ldxflib -pthread")
set(HULA_PC_CFLAGS "-std=c++20")
if(HULA_WITH_OCCT)
  string(PREPEND HULA_PC_CFLAGS "-I${OpenCASCADE_INCLUDE_DIR} -DHULA_WITH_OCCT ")
  get_target_property(hula_occt_tks hula_occt INTERFACE_LINK_LIBRARIES)
  list(TRANSFORM hula_occt_tks PREPEND "-l")
  list(JOIN hula_occt_tks " " hula_occt_tks)
  string(PREPEND HULA_PC_DEP_LIBS "-L${OpenCASCADE_LIBRARY_DIR} ${hula_occt_tks} ")
endif()
# Relocatable: the prefix is found from the .pc file's own directory, so `cmake --install
# --prefix DIR` works without reconfiguring.
file(RELATIVE_PATH HULA_PC_PREFIX_FROM_PCDIR ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" HULA_PC_PREFIX_FROM_PCDIR "${HULA_PC_PREFIX_FROM_PCDIR}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/hulahoops.pc.in ${PROJECT_BINARY_DIR}/hulahoops.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/hulahoops.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
