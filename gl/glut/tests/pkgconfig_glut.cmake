# Installs the built project into a scratch prefix, builds the GLUT demo as a user would,
# `cc demo.c $(pkg-config --cflags --libs velocity-glut) -lm`, and runs it for two frames
# on SDL's dummy video driver.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
set(ENV{PKG_CONFIG_PATH} ${WORK_DIR}/prefix/${LIBDIR}/pkgconfig)
execute_process(COMMAND pkg-config --cflags --libs velocity-glut OUTPUT_VARIABLE flags RESULT_VARIABLE rc
                OUTPUT_STRIP_TRAILING_WHITESPACE)
if(rc)
  message(FATAL_ERROR "pkg-config does not find velocity-glut (${rc})")
endif()
message(STATUS "pkg-config --cflags --libs velocity-glut: ${flags}")
separate_arguments(flags UNIX_COMMAND "${flags}")
execute_process(COMMAND ${CC} ${EXTRA} ${SOURCE} ${flags} -lm -o ${WORK_DIR}/demo RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "cc demo.c $(pkg-config --cflags --libs velocity-glut) failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env LD_LIBRARY_PATH=${WORK_DIR}/prefix/${LIBDIR} SDL_VIDEODRIVER=dummy
                        SDL_AUDIODRIVER=dummy VELOCITY_GLUT_FRAMES=2 ${WORK_DIR}/demo
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(rc OR NOT out MATCHES "main loop left after 2 frames")
  message(FATAL_ERROR "the demo built against the installed velocity-glut failed (${rc})")
endif()
