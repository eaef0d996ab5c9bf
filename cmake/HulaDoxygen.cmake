# SPDX-License-Identifier: MIT
# `cmake --build build/ci --target doxygen`: HTML reference of the public headers
# (src/hula/<module>/*.hpp, detail/ and testing/ left out) in build/ci/doxygen/html.
# Generated, never committed (STYLE.md). Absent when Debian's doxygen is not installed.
find_package(Doxygen QUIET)
if(DOXYGEN_FOUND)
  set(DOXYGEN_PROJECT_NAME "HulaHoops")
  set(DOXYGEN_PROJECT_NUMBER ${PROJECT_VERSION})
  set(DOXYGEN_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/doxygen)
  set(DOXYGEN_FILE_PATTERNS "*.hpp")
  set(DOXYGEN_EXCLUDE_PATTERNS "*/detail/*" "*/testing/*")
  set(DOXYGEN_EXTRACT_ALL NO)
  set(DOXYGEN_WARN_IF_UNDOCUMENTED NO)
  set(DOXYGEN_GENERATE_LATEX NO)
  set(DOXYGEN_STRIP_FROM_PATH ${PROJECT_SOURCE_DIR}/src)
  set(DOXYGEN_STRIP_FROM_INC_PATH ${PROJECT_SOURCE_DIR}/src)
  set(DOXYGEN_USE_MDFILE_AS_MAINPAGE ${PROJECT_SOURCE_DIR}/README.md)
  doxygen_add_docs(doxygen ${PROJECT_SOURCE_DIR}/src/hula ${PROJECT_BINARY_DIR}/include/hula ${PROJECT_SOURCE_DIR}/README.md
    COMMENT "Doxygen reference of the public headers")
endif()
