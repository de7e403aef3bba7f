# SPDX-License-Identifier: MIT
# Where Guile looks for extensions, modules and their compiled .go files,
# from guile-3.0.pc, made relative to Guile's own prefix so that they can be
# re-rooted at any install prefix: installed into /usr they are exactly the
# directories a plain `guile' searches with no environment variables.
#   DS_GUILE_EXTENSION_DIR   e.g. lib/x86_64-linux-gnu/guile/3.0/extensions
#   DS_GUILE_SITE_DIR        e.g. share/guile/site/3.0
#   DS_GUILE_SITE_CCACHE_DIR e.g. lib/x86_64-linux-gnu/guile/3.0/site-ccache
pkg_get_variable(_guile_prefix guile-3.0 prefix)
foreach(pair "EXTENSION_DIR;extensiondir" "SITE_DIR;sitedir" "SITE_CCACHE_DIR;siteccachedir")
  list(GET pair 0 name)
  list(GET pair 1 variable)
  pkg_get_variable(_dir guile-3.0 ${variable})
  if(NOT _dir)
    message(FATAL_ERROR "guile-3.0.pc has no ${variable} variable")
  endif()
  file(RELATIVE_PATH DS_GUILE_${name} ${_guile_prefix} ${_dir})
endforeach()
