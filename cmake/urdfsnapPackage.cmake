# The Debian package, made by CPack (scripts/package.sh): urdfsnap_<version>_<arch>.deb with what
# `cmake --install` installs (the binary, its modules in lib/urdfsnap/, the static libraries, their
# headers, the CMake package, the Python package when URDFSNAP_BUILD_PYTHON) plus the man pages,
# under URDFSNAP_PACKAGE_PREFIX (/usr).
#
# Depends: what dpkg-shlibdeps finds for the shared libraries of the binary (urdfdom,
# yaml-cpp, tinyxml2, FreeType, expat, zlib, the C++ runtime) and of its modules (assimp; FFmpeg,
# libwebp, zstd; cpp-httplib), plus what is loaded at run time and so is
# invisible to it: URDFSNAP_PACKAGE_RUNTIME_DEPENDS below. Linking the C++ libraries
# (find_package(urdfsnap)) also needs the -dev packages of those libraries: Suggests, so that CI
# runners installing the package for the command line do not get them.
execute_process(COMMAND dpkg --print-architecture OUTPUT_VARIABLE urdfsnap_deb_arch
  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT urdfsnap_deb_arch)
  set(urdfsnap_deb_arch unknown)
endif()

# libOSMesa is dlopen'ed (src/gl/gl_context.cpp); the TF name font is read from
# fonts-liberation's folder (src/texture/glyph_atlas.cpp). A backend or data file loaded at run
# time belongs here.
set(URDFSNAP_PACKAGE_RUNTIME_DEPENDS "libosmesa6, fonts-liberation | fonts-liberation2"
  CACHE STRING "Depends of the Debian package that dpkg-shlibdeps cannot see")

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME urdfsnap)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "urdfsnap maintainers <urdfsnap@users.noreply.invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "RViz-like images of URDF/xacro robots, headless")
# the extended description; CPack indents it and writes the empty line as Debian's " ."
set(CPACK_PACKAGE_DESCRIPTION "urdfsnap renders a robot description (URDF, or xacro expanded in
process) in given joint positions into PNG images that look like ROS RViz, with no display, GPU
or ROS install (OSMesa's llvmpipe). It checks snapshot suites against golden images (HTML and
JUnit reports, sharded over CI workers and merged), expands xacro and compares images.

The package also holds urdfsnap's C++ libraries, headers and CMake package
(find_package(urdfsnap)); linking them needs the -dev packages listed in Suggests.")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE ${urdfsnap_deb_arch})
set(CPACK_DEBIAN_FILE_NAME "urdfsnap_${PROJECT_VERSION}_${urdfsnap_deb_arch}.deb")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${URDFSNAP_PACKAGE_RUNTIME_DEPENDS}")
if(URDFSNAP_BUILD_PYTHON)
  # the Python package in /usr/lib/python3/dist-packages: its module is built for this Python's
  # ABI (as Debian's python3 packages depend: >= 3.N~, << 3.N+1) and imports numpy
  math(EXPR urdfsnap_python_next "${Python3_VERSION_MINOR} + 1")
  string(APPEND CPACK_DEBIAN_PACKAGE_DEPENDS ", python3 (>= ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}~), "
         "python3 (<< ${Python3_VERSION_MAJOR}.${urdfsnap_python_next}), python3-numpy")
endif()
# what find_package(urdfsnap) needs (cmake/urdfsnapConfig.cmake.in: keep the two in step)
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "liburdfdom-dev, libeigen3-dev, libtinyxml2-dev, libyaml-cpp-dev, nlohmann-json3-dev, zlib1g-dev, libjpeg-dev, libfreetype-dev, libexpat1-dev, pkg-config, libzstd-dev, liblz4-dev, libsqlite3-dev, libqhull-dev, libdeflate-dev")
set(CPACK_PACKAGING_INSTALL_PREFIX ${URDFSNAP_PACKAGE_PREFIX})
set(CPACK_STRIP_FILES ON)
include(CPack)
