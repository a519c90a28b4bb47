# Installs the built project into a scratch prefix, builds a C program as a user would,
# `cc prog.c $(pkg-config --cflags --libs PACKAGE) -lm`, and runs it.
#   cmake -DBUILD_DIR=... -DWORK_DIR=... -DLIBDIR=... -DSOURCE=prog.c -DCC=... [-DEXTRA=flags]
#         [-DPACKAGE=velocity-gl] [-DRUN_ENV=VAR=value|...] [-DEXPECT_OUTPUT=regex] -P pkgconfig.cmake
# Without EXPECT_OUTPUT the program gets WORK_DIR/out as its argument and must write
# ortho.ppm there (the conformance programs do); with it, its output must match.
if(NOT PACKAGE)
  set(PACKAGE velocity-gl)
endif()
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
set(ENV{PKG_CONFIG_PATH} ${WORK_DIR}/prefix/${LIBDIR}/pkgconfig)
execute_process(COMMAND pkg-config --cflags --libs ${PACKAGE} OUTPUT_VARIABLE flags RESULT_VARIABLE rc
                OUTPUT_STRIP_TRAILING_WHITESPACE)
if(rc)
  message(FATAL_ERROR "pkg-config does not find ${PACKAGE} (${rc})")
endif()
message(STATUS "pkg-config --cflags --libs ${PACKAGE}: ${flags}")
separate_arguments(flags UNIX_COMMAND "${flags}")
execute_process(COMMAND ${CC} ${EXTRA} ${SOURCE} ${flags} -lm -o ${WORK_DIR}/prog RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "cc prog.c $(pkg-config --cflags --libs ${PACKAGE}) failed (${rc})")
endif()
string(REPLACE "|" ";" run_env "${RUN_ENV}")
set(run ${CMAKE_COMMAND} -E env LD_LIBRARY_PATH=${WORK_DIR}/prefix/${LIBDIR} ${run_env} ${WORK_DIR}/prog)
if(EXPECT_OUTPUT)
  execute_process(COMMAND ${run} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(rc OR NOT out MATCHES "${EXPECT_OUTPUT}")
    message(FATAL_ERROR "the program built against the installed ${PACKAGE} failed (${rc})")
  endif()
else()
  file(MAKE_DIRECTORY ${WORK_DIR}/out)
  execute_process(COMMAND ${run} ${WORK_DIR}/out RESULT_VARIABLE rc)
  if(rc OR NOT EXISTS ${WORK_DIR}/out/ortho.ppm)
    message(FATAL_ERROR "the program built against the installed ${PACKAGE} failed (${rc})")
  endif()
endif()
