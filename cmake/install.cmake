# SPDX-License-Identifier: MIT
# `cmake --install build [--prefix P]': the host, the core library and its
# public headers for C++ programs (with downstroke.pc and a CMake package),
# the Guile extension and the Scheme modules where Guile looks for them
# (cmake/guile_dirs.cmake), the docs and the demos. Installed into /usr, a
# plain `guile' runs (use-modules (downstroke)) with no environment variables;
# README.md "Install" lists the variables another prefix needs.

install(TARGETS downstroke-installed RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Found by name (load-extension "libdownstroke-guile") in Guile's extension
# directory, the way other Guile libraries are.
install(TARGETS downstroke-guile LIBRARY DESTINATION ${DS_GUILE_EXTENSION_DIR})

install(TARGETS downstroke-core EXPORT DownstrokeTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
# The public headers (cmake/public_header_list.cmake), under include/downstroke/
# so that a program includes them as <downstroke/frame.hpp>; never src/detail/,
# the renderer or the map readers' helpers.
include(${PROJECT_SOURCE_DIR}/cmake/public_header_list.cmake)
foreach(header ${DS_PUBLIC_HEADERS})
  get_filename_component(_dir ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/src/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/downstroke/${_dir})
endforeach()

set(_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/Downstroke)
install(EXPORT DownstrokeTargets NAMESPACE Downstroke:: DESTINATION ${_cmake_dir})
include(CMakePackageConfigHelpers)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/DownstrokeConfig.cmake.in
  ${CMAKE_BINARY_DIR}/DownstrokeConfig.cmake INSTALL_DESTINATION ${_cmake_dir})
# 0.x: a minor version may break the API, so only the same minor is compatible.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/DownstrokeConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/DownstrokeConfig.cmake ${CMAKE_BINARY_DIR}/DownstrokeConfigVersion.cmake
  DESTINATION ${_cmake_dir})

# downstroke.pc finds its prefix from its own location, so that one file is
# right for --prefix P and for the .deb alike.
set(_pc_dir ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
file(RELATIVE_PATH DS_PC_TO_PREFIX ${CMAKE_INSTALL_PREFIX}/${_pc_dir} ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" DS_PC_TO_PREFIX "${DS_PC_TO_PREFIX}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/downstroke.pc.in ${CMAKE_BINARY_DIR}/downstroke.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/downstroke.pc DESTINATION ${_pc_dir})

# The modules and, next to Guile's own compiled files, their .go (installed
# after the sources, so never older than them: Guile then loads them as is).
install(FILES ${PROJECT_SOURCE_DIR}/scheme/downstroke.scm DESTINATION ${DS_GUILE_SITE_DIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scheme/downstroke DESTINATION ${DS_GUILE_SITE_DIR}
  FILES_MATCHING PATTERN "*.scm")
install(DIRECTORY ${CMAKE_BINARY_DIR}/go/ DESTINATION ${DS_GUILE_SITE_CCACHE_DIR}
  FILES_MATCHING PATTERN "*.go")

install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
# What `downstroke new' copies (the installed host looks here, beside the demos).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/templates/ DESTINATION ${CMAKE_INSTALL_DATADIR}/downstroke/templates)
# Each demo finds its maps and sounds next to itself: downstroke PREFIX/share/downstroke/demo/platformer.scm.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/demo/ DESTINATION ${CMAKE_INSTALL_DATADIR}/downstroke/demo
  PATTERN "CMakeLists.txt" EXCLUDE)
