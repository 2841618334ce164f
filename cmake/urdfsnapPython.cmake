# The Python package `import urdfsnap` (src/python/ builds its extension module, python/urdfsnap/
# holds the package): URDFSNAP_BUILD_PYTHON, on by default when Python 3 with its headers, numpy
# and pybind11 are found (Debian: python3-dev python3-numpy pybind11-dev), off in sanitizer builds
# (a sanitized module cannot be loaded into an unsanitized Python). The package is staged in
# <build>/python/urdfsnap (PYTHONPATH for the tests), installed into URDFSNAP_PYTHON_INSTALL_DIR.
#
# Debian's /usr/bin/python3 is the one looked for first: it is where python3-numpy lives and what
# the .deb installs for, and a pyenv or conda python3 earlier on PATH would otherwise win.
# -DPython3_EXECUTABLE=... builds for another Python (pip does so, see setup.py).
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3)
endif()
find_package(Python3 3.9 COMPONENTS Interpreter Development.Module NumPy QUIET)
find_package(pybind11 2.6 CONFIG QUIET)
set(urdfsnap_python_default OFF)
if(Python3_FOUND AND pybind11_FOUND AND NOT URDFSNAP_SANITIZE)
  set(urdfsnap_python_default ON)
endif()
option(URDFSNAP_BUILD_PYTHON "Build the Python package (pybind11, numpy)" ${urdfsnap_python_default})
set(URDFSNAP_PYTHON_INSTALL_DIR lib/python3/dist-packages CACHE STRING
  "Where `cmake --install` puts the Python package, relative to the prefix (Debian's dist-packages)")
if(URDFSNAP_BUILD_PYTHON)
  if(NOT Python3_FOUND OR NOT pybind11_FOUND)
    message(FATAL_ERROR "URDFSNAP_BUILD_PYTHON needs Python 3 with headers and numpy, and pybind11 "
                        "(Debian: python3-dev python3-numpy pybind11-dev)")
  endif()
  add_subdirectory(src/python)
endif()
