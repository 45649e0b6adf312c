# The Python module `ncurve` (docs/python.md): pybind11 over the library, for Debian's
# /usr/bin/python3 (pybind11-dev, python3-dev and python3-numpy are Debian's packages for it; a
# python3 earlier on PATH, such as pyenv's, has neither). Built into build/python/ (import with
# PYTHONPATH=build/python); cmake --install puts it in that interpreter's dist-packages.
set(NCURVE_PYTHON_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "the Python interpreter the module is built for")
set(ncurve_python_found OFF)
if(NOT DEFINED NCURVE_PYTHON OR NCURVE_PYTHON)
  set(Python3_EXECUTABLE ${NCURVE_PYTHON_EXECUTABLE})
  find_package(Python3 3.8 QUIET COMPONENTS Interpreter Development.Module NumPy)
  if(Python3_FOUND)
    find_package(pybind11 2.6 CONFIG QUIET)  # uses the Python3 found above
  endif()
  if(Python3_FOUND AND Python3_NumPy_FOUND AND pybind11_FOUND)
    set(ncurve_python_found ON)
  endif()
endif()
# a sanitizer's library cannot be loaded into an uninstrumented python: off in those builds
if(NCURVE_SANITIZE OR NCURVE_FUZZ)
  set(ncurve_python_default OFF)
else()
  set(ncurve_python_default ${ncurve_python_found})
endif()
option(NCURVE_PYTHON "Build the Python module (pybind11, NumPy; default: on when found)" ${ncurve_python_default})
if(NOT NCURVE_PYTHON)
  return()
endif()
if(NOT ncurve_python_found)
  message(FATAL_ERROR "NCURVE_PYTHON: pybind11 and NumPy's headers were not found for ${NCURVE_PYTHON_EXECUTABLE}: "
                      "install Debian's pybind11-dev python3-dev python3-numpy (scripts/setup.sh does), or "
                      "configure with -DNCURVE_PYTHON=OFF")
endif()

# The module is a shared object: the libraries it links are built position-independent, with
# calls between their own functions still bound at link time (no interposition), as in the binary.
set_target_properties(ncurve ncurve_app PROPERTIES POSITION_INDEPENDENT_CODE ON)
target_compile_options(ncurve PRIVATE -fno-semantic-interposition)
target_compile_options(ncurve_app PRIVATE -fno-semantic-interposition)

# NO_EXTRAS: no link-time optimisation of the module (it would recompile the library at each link)
pybind11_add_module(ncurve_python MODULE NO_EXTRAS
  src/python/module.cpp
  src/python/common/cli_args.cpp
  src/python/common/diagnostic.cpp
  src/python/common/run_args.cpp
  src/python/run/move_records.cpp
  src/python/run/run.cpp
  src/python/run/steps.cpp
  src/python/analyze/analyze.cpp
  src/python/analyze/circle.cpp
  src/python/helicoid/helicoid.cpp
  src/python/verify/verify.cpp
  src/python/gen/gen.cpp
  src/python/geom/curve.cpp)
set_target_properties(ncurve_python PROPERTIES OUTPUT_NAME ncurve LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/python)
target_link_libraries(ncurve_python PRIVATE ncurve_app)

# Where it is installed (relative to the prefix): the interpreter's own dist-packages for this
# prefix, lib/python3.X/dist-packages on Debian (/usr/local/lib/python3.X/dist-packages is on its path).
execute_process(COMMAND ${Python3_EXECUTABLE} -c
  "import os, sysconfig; p = os.path.relpath(sysconfig.get_path('platlib', vars={'base': '/P', 'platbase': '/P'}), '/P'); print(p[6:] if sysconfig.get_default_scheme() == 'posix_local' and p.startswith('local/') else p)"
  OUTPUT_VARIABLE ncurve_python_site OUTPUT_STRIP_TRAILING_WHITESPACE)
set(NCURVE_PYTHON_INSTALL_DIR ${ncurve_python_site} CACHE PATH "where cmake --install puts the Python module (relative to the prefix)")
include(GNUInstallDirs)
# the shipped profiles and macros, found from the installed module's folder (or the source tree's)
file(RELATIVE_PATH ncurve_python_share ${CMAKE_INSTALL_PREFIX}/${NCURVE_PYTHON_INSTALL_DIR}
     ${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_DATADIR}/ncurve)
target_compile_definitions(ncurve_python PRIVATE NCURVE_VERSION="${PROJECT_VERSION}"
                           NCURVE_SOURCE_DIR="${PROJECT_SOURCE_DIR}" NCURVE_PYTHON_SHARE="${ncurve_python_share}")
# the type stubs beside the module, for editors and type checkers
configure_file(src/python/ncurve.pyi ${CMAKE_BINARY_DIR}/python/ncurve.pyi COPYONLY)
install(TARGETS ncurve_python LIBRARY DESTINATION ${NCURVE_PYTHON_INSTALL_DIR})
install(FILES src/python/ncurve.pyi DESTINATION ${NCURVE_PYTHON_INSTALL_DIR})
