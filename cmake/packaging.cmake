# SPDX-License-Identifier: MIT
# `cpack -G DEB' (tools/make-deb.sh): downstroke_<version>_<arch>.deb, which
# installs into /usr, where a plain `guile' finds the modules and the
# extension with no environment variables.
set(CPACK_PACKAGE_NAME downstroke)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "Downstroke")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "2D tile-and-AABB physics engine with Guile Scheme bindings")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "Downstroke maintainers <downstroke@localhost>")
set(CPACK_DEBIAN_PACKAGE_SECTION games)
# dpkg-shlibdeps computes the libraries' packages (libguile, SDL2, tinyxml2…);
# guile-3.0 is the interpreter itself, which no shared library pulls in.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "guile-3.0")
include(CPack)
