# SPDX-License-Identifier: MIT
# hula::warnings: the warning set applied to our own targets only (never to
# Debian's headers, which are included as SYSTEM). HULA_WERROR turns them into
# errors; CI sets it through the `ci` preset.
add_library(hula_warnings INTERFACE)
add_library(hula::warnings ALIAS hula_warnings)
target_compile_options(hula_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast
  -Wcast-align -Woverloaded-virtual -Wnull-dereference -Wdouble-promotion
  -Wimplicit-fallthrough)
if(HULA_WERROR)
  target_compile_options(hula_warnings INTERFACE -Werror)
endif()
