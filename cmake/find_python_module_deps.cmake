# What the Python module (python/) needs: sets VELOCITY_PYTHON_DEPS_FOUND.
#
# The interpreter: the first python3 on PATH that has numpy, else Debian's own. (A
# pyenv or other python3 earlier on PATH often lacks the Debian packages.) Pass
# -DPython3_EXECUTABLE=... to choose.
if(NOT Python3_EXECUTABLE)
  find_program(velocity_path_python python3)
  foreach(candidate ${velocity_path_python} /usr/bin/python3)
    if(candidate AND EXISTS ${candidate})
      execute_process(COMMAND ${candidate} -c "import numpy" RESULT_VARIABLE no_numpy OUTPUT_QUIET ERROR_QUIET)
      if(no_numpy EQUAL 0)
        set(Python3_EXECUTABLE ${candidate} CACHE FILEPATH "The Python the module is built for")
        break()
      endif()
    endif()
  endforeach()
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module NumPy)
find_package(pybind11 CONFIG QUIET)
set(VELOCITY_PYTHON_DEPS_FOUND OFF)
if(Python3_FOUND AND Python3_NumPy_FOUND AND pybind11_FOUND)
  set(VELOCITY_PYTHON_DEPS_FOUND ON)
endif()
