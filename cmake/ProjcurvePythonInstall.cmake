# SPDX-License-Identifier: BSD-3-Clause
# Install rules of the Python package (python/projcurve), component
# "python":
#   cmake --install build --component python [--prefix P]
# installs it into P/${PROJCURVE_PYTHON_INSTALL_DIR}; with
# -DPROJCURVE_INSTALL_PYTHON=ON a plain `cmake --install` installs it too.
# The installed package carries _install_location.py, the path from itself
# to the installed library (relative unless the libdir is absolute), so it
# loads the library of its own prefix wherever the prefix is moved.
option(PROJCURVE_INSTALL_PYTHON "Install the Python package with the default component" OFF)

if(NOT DEFINED PROJCURVE_PYTHON_INSTALL_DIR)
  set(python_dir "lib/python3/site-packages")
  find_package(Python3 COMPONENTS Interpreter QUIET)
  if(Python3_Interpreter_FOUND)
    # the prefix scheme's purelib relative to the prefix: lib/python3.X/site-packages
    execute_process(COMMAND ${Python3_EXECUTABLE} -c
      "import sysconfig; print(sysconfig.get_path('purelib', 'posix_prefix', {'base': '', 'platbase': ''}).lstrip('/'))"
      OUTPUT_VARIABLE python_dir_found OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
    if(rc EQUAL 0 AND python_dir_found)
      set(python_dir ${python_dir_found})
    endif()
  endif()
  set(PROJCURVE_PYTHON_INSTALL_DIR ${python_dir} CACHE STRING
      "Where the Python package is installed, relative to the prefix")
endif()

if(IS_ABSOLUTE ${CMAKE_INSTALL_LIBDIR})
  set(PROJCURVE_PY_LIBDIR ${CMAKE_INSTALL_LIBDIR})
else()
  file(RELATIVE_PATH PROJCURVE_PY_LIBDIR /root/${PROJCURVE_PYTHON_INSTALL_DIR}/projcurve
       /root/${CMAKE_INSTALL_LIBDIR})
endif()
if(WIN32)
  set(PROJCURVE_PY_LIBDIR ${CMAKE_INSTALL_BINDIR})
endif()
file(CONFIGURE OUTPUT ${PROJECT_BINARY_DIR}/python/_install_location.py CONTENT
"# SPDX-License-Identifier: BSD-3-Clause
# Written by cmake --install: the installed library's directory, relative
# to this package's directory unless absolute.
LIBDIR = \"@PROJCURVE_PY_LIBDIR@\"
" @ONLY)

set(python_exclude "")
if(NOT PROJCURVE_INSTALL_PYTHON)
  set(python_exclude EXCLUDE_FROM_ALL)
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/python/projcurve
        DESTINATION ${PROJCURVE_PYTHON_INSTALL_DIR} COMPONENT python ${python_exclude}
        FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
install(FILES ${PROJECT_BINARY_DIR}/python/_install_location.py
        DESTINATION ${PROJCURVE_PYTHON_INSTALL_DIR}/projcurve COMPONENT python ${python_exclude})
