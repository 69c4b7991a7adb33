# Finds what the Python module needs and sets CANOPY_PYTHON_ENABLED.
#
# The interpreter: Debian's /usr/bin/python3 when it exists, because pybind11, NumPy and pytest
# come from Debian packages (python3-pybind11, python3-numpy, python3-pytest) and another
# python3 earlier on PATH (pyenv, a venv) would not see them. -DPython3_EXECUTABLE=... picks
# another one.
set(CANOPY_PYTHON_ENABLED OFF)
# canopy_python_ready(TARGET): a static library the module links into a shared object.
function(canopy_python_ready target)
  if(CANOPY_PYTHON_ENABLED)
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    # Without it GCC may not inline or call directly a function with default visibility in -fPIC
    # code (it could be interposed at load time): slower than the -fPIE code of the CLI.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
      target_compile_options(${target} PRIVATE -fno-semantic-interposition)
    endif()
  endif()
endfunction()

if(NOT CANOPY_PYTHON)
  return()
endif()
if(CANOPY_SANITIZE OR CANOPY_FUZZ)
  # An ASan-instrumented module cannot be loaded into an interpreter that was not linked with the
  # ASan runtime (it must come first in the process), so these builds leave Python out.
  message(STATUS "Python module: off under CANOPY_SANITIZE / CANOPY_FUZZ")
  return()
endif()
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python the module is built for")
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module NumPy)
if(NOT (Python3_Interpreter_FOUND AND Python3_Development.Module_FOUND AND Python3_NumPy_FOUND))
  message(STATUS "Python module: off (needs Python 3 headers and NumPy: python3-dev, python3-numpy)")
  return()
endif()
set(PYBIND11_FINDPYTHON ON)
find_package(pybind11 2.6 CONFIG QUIET)
if(NOT pybind11_FOUND)
  message(STATUS "Python module: off (pybind11 not found: pybind11-dev)")
  return()
endif()
set(CANOPY_PYTHON_ENABLED ON)
message(STATUS "Python module: on, for ${Python3_EXECUTABLE} (${Python3_VERSION})")
