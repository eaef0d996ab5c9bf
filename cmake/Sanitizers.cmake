# SPDX-License-Identifier: MIT
# hula::sanitize: sanitizer flags for our targets, from HULA_SANITIZE.
add_library(hula_sanitize INTERFACE)
add_library(hula::sanitize ALIAS hula_sanitize)
if(HULA_SANITIZE)
  target_compile_options(hula_sanitize INTERFACE -fsanitize=${HULA_SANITIZE} -fno-omit-frame-pointer)
  target_link_options(hula_sanitize INTERFACE -fsanitize=${HULA_SANITIZE})
endif()
