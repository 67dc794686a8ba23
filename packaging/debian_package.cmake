# The Debian package: `cpack -G DEB` in the build folder writes maze_mapper_VERSION_ARCH.deb
# (Debian's package names have no '_': the package itself is maze-mapper). Included last by
# the top CMakeLists.txt, once python/ has said whether the module is built and for which
# Python. tests/package_deb.sh builds it, runs lintian on it (no error, no warning), installs,
# uses and removes it.

include(GNUInstallDirs)
set(CPACK_PACKAGE_NAME maze-mapper)
set(MAZE_MAPPER_PACKAGE_MAINTAINER "maze_mapper maintainers <maintainers@users.noreply.h-seed-64e759d4.example>"
    CACHE STRING "The Debian package's Maintainer, \"Name <address>\"")
set(_debian_dir ${CMAKE_BINARY_DIR}/packaging/debian)
# The Debian revision: the package is made apart from the program's source (a Debian
# changelog, changelog.Debian.gz, not a native package's changelog.gz).
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(MAZE_MAPPER_DEB_VERSION "${PROJECT_VERSION}-${CPACK_DEBIAN_PACKAGE_RELEASE}")

# Debian's doc files: the changelog (compressed, gzip -n: the same bytes each build) and the
# copyright file, beside README in the documentation folder.
configure_file(${CMAKE_CURRENT_LIST_DIR}/debian/changelog.in ${_debian_dir}/changelog @ONLY)
configure_file(${CMAKE_CURRENT_LIST_DIR}/debian/copyright.in ${_debian_dir}/copyright @ONLY)
add_custom_command(
  OUTPUT ${_debian_dir}/changelog.Debian.gz
  COMMAND gzip -9 -n -c ${_debian_dir}/changelog > ${_debian_dir}/changelog.Debian.gz
  DEPENDS ${_debian_dir}/changelog
  VERBATIM)
add_custom_target(maze_mapper_debian_changelog ALL DEPENDS ${_debian_dir}/changelog.Debian.gz)
install(FILES ${_debian_dir}/changelog.Debian.gz ${_debian_dir}/copyright DESTINATION ${CMAKE_INSTALL_DOCDIR})
# lintian's overrides: the one tag that does not apply to a package made outside Debian.
install(FILES ${CMAKE_CURRENT_LIST_DIR}/debian/lintian-overrides RENAME ${CPACK_PACKAGE_NAME}
        DESTINATION ${CMAKE_INSTALL_DATADIR}/lintian/overrides)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "${MAZE_MAPPER_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "simulated robot that maps grid mazes into a log-odds occupancy grid")
# Debian's extended description, below that summary: lines of at most 79 characters (CPack
# indents each by one).
set(CPACK_PACKAGE_DESCRIPTION "A simulated robot explores a grid maze cell by cell through a Webots-compatible
device API and maps it into a 4D log-odds occupancy grid, printed as text; with
the course's robots, mapping models and worlds, and a Python module for
students' controllers.")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Beside those: Cairo, which the program loads when it first draws a picture
# (app/picture/cairo_library.hpp) and so names in no link, and the font the pictures' text is
# drawn in (app/picture/drawing.hpp), which no shared library names. The Python module is
# built for one Python (its file name says which) and hands the grid out as a NumPy array.
set(_depends "libcairo2 (>= 1.16), fonts-dejavu-core")
if(MAZE_MAPPER_PYTHON_VERSION)
  string(REPLACE "." ";" _python_version "${MAZE_MAPPER_PYTHON_VERSION}")
  list(GET _python_version 0 _major)
  list(GET _python_version 1 _minor)
  math(EXPR _next_minor "${_minor} + 1")
  string(APPEND _depends ", python3 (>= ${MAZE_MAPPER_PYTHON_VERSION}), python3 (<< ${_major}.${_next_minor}), python3-numpy")
  configure_file(${CMAKE_CURRENT_LIST_DIR}/debian/prerm.in ${_debian_dir}/prerm @ONLY
                 FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
  set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${_debian_dir}/prerm)
  set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
endif()
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${_depends}")
# Recommended: bash-completion, without which bash completes nothing (the package's completion
# goes where it loads completions from); and the libraries the course's own library imports
# (fairis_lib: pandas, matplotlib), so that a course's controller runs as it is.
set(_recommends "bash-completion")
if(MAZE_MAPPER_PYTHON_VERSION)
  string(APPEND _recommends ", python3-pandas, python3-matplotlib")
endif()
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "${_recommends}")
find_program(MAZE_MAPPER_DPKG dpkg)
if(MAZE_MAPPER_DPKG)
  execute_process(COMMAND ${MAZE_MAPPER_DPKG} --print-architecture
                  OUTPUT_VARIABLE CPACK_DEBIAN_PACKAGE_ARCHITECTURE OUTPUT_STRIP_TRAILING_WHITESPACE)
else()
  set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE amd64)
endif()
set(CPACK_DEBIAN_FILE_NAME "maze_mapper_${PROJECT_VERSION}_${CPACK_DEBIAN_PACKAGE_ARCHITECTURE}.deb")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
include(CPack)
