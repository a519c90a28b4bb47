# Installs the built project into a scratch prefix, builds a Mesa-style C program with
# `cc prog.c $(pkg-config --cflags --libs velocity-gl) -lm`, runs it.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
set(ENV{PKG_CONFIG_PATH} ${WORK_DIR}/prefix/${LIBDIR}/pkgconfig)
execute_process(COMMAND pkg-config --cflags --libs velocity-gl OUTPUT_VARIABLE flags RESULT_VARIABLE rc
                OUTPUT_STRIP_TRAILING_WHITESPACE)
if(rc)
  message(FATAL_ERROR "pkg-config does not find velocity-gl (${rc})")
endif()
message(STATUS "pkg-config --cflags --libs velocity-gl: ${flags}")
separate_arguments(flags UNIX_COMMAND "${flags}")
execute_process(COMMAND ${CC} ${EXTRA} ${SOURCE} ${flags} -lm -o ${WORK_DIR}/prog RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "cc prog.c $(pkg-config --cflags --libs velocity-gl) failed (${rc})")
endif()
file(MAKE_DIRECTORY ${WORK_DIR}/out)
execute_process(COMMAND ${CMAKE_COMMAND} -E env LD_LIBRARY_PATH=${WORK_DIR}/prefix/${LIBDIR} ${WORK_DIR}/prog
                        ${WORK_DIR}/out RESULT_VARIABLE rc)
if(rc OR NOT EXISTS ${WORK_DIR}/out/ortho.ppm)
  message(FATAL_ERROR "the program built against the installed velocity-gl failed (${rc})")
endif()
