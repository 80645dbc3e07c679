# Fails when the sim library calls a libm function other than the exactly rounded ones:
# the transcendental functions (sin, exp, atan2, ...) differ in their last bits between
# C libraries and CPUs, so the sim has its own (sim/core/DetMath.h).
#   cmake -DNM=nm -DLIB=libspindrift_sim.a -DLIBM=/path/libm.so.6 -P sim_symbols.cmake
# Every symbol the library's objects leave undefined is looked up among the ones libm
# defines; those not in the list of exact functions below are errors, named with the
# object that calls them.
foreach(var NM LIB LIBM)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "sim_symbols.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT EXISTS "${LIBM}")
  message(FATAL_ERROR "sim_symbols.cmake: no libm at '${LIBM}' (the compiler's -print-file-name=libm.so.6): "
                      "cannot tell libm's functions from others")
endif()

# Correctly rounded or exact in every C library (IEEE 754 or C's own definition), and the
# rounding-mode query the sim's environment check makes.
set(exact
  sqrt sqrtf fabs fabsf floor floorf ceil ceilf trunc truncf round roundf lround lroundf llround llroundf
  rint rintf lrint lrintf nearbyint nearbyintf fmod fmodf remainder remainderf fmin fminf fmax fmaxf
  copysign copysignf ldexp ldexpf scalbn scalbnf frexp frexpf modf modff fegetround)

execute_process(COMMAND "${NM}" -D --defined-only "${LIBM}" OUTPUT_VARIABLE libm_out RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sim_symbols.cmake: '${NM} -D ${LIBM}' failed (${rc})")
endif()
string(REGEX MATCHALL "[ \t][TtWwi] [A-Za-z_][A-Za-z0-9_]*" libm_defs "${libm_out}")
set(libm_names "")
foreach(d IN LISTS libm_defs)
  string(REGEX REPLACE "^[ \t][TtWwi] " "" name "${d}")
  list(APPEND libm_names "${name}")
endforeach()
list(LENGTH libm_names n_libm)
if(n_libm LESS 100)
  message(FATAL_ERROR "sim_symbols.cmake: read only ${n_libm} functions from ${LIBM}; is it libm?")
endif()
list(FIND libm_names sinf has_sinf)
if(has_sinf EQUAL -1)
  message(FATAL_ERROR "sim_symbols.cmake: ${LIBM} does not define sinf; is it libm?")
endif()

# "lib.a:Object.cpp.o:                 U sinf" per undefined symbol and object.
execute_process(COMMAND "${NM}" -A -u "${LIB}" OUTPUT_VARIABLE lib_out RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sim_symbols.cmake: '${NM} -A -u ${LIB}' failed (${rc})")
endif()
string(REPLACE "\n" ";" lines "${lib_out}")
set(found "")
set(n_undefined 0)
foreach(line IN LISTS lines)
  if(NOT line MATCHES "^(.*):[ \t]+U[ \t]+([A-Za-z_][A-Za-z0-9_.@]*)$")
    continue()
  endif()
  math(EXPR n_undefined "${n_undefined} + 1")
  set(object "${CMAKE_MATCH_1}")
  string(REGEX REPLACE "@.*$" "" name "${CMAKE_MATCH_2}")
  list(FIND libm_names "${name}" in_libm)
  list(FIND exact "${name}" is_exact)
  if(in_libm GREATER -1 AND is_exact EQUAL -1)
    get_filename_component(object_name "${object}" NAME)
    list(APPEND found "${object_name} calls libm's ${name}")
  endif()
endforeach()
if(n_undefined EQUAL 0)
  message(FATAL_ERROR "sim_symbols.cmake: found no undefined symbols in ${LIB}: nm's output was not understood")
endif()
if(found)
  list(REMOVE_DUPLICATES found)
  list(SORT found)
  list(JOIN found "\n  " text)
  message(FATAL_ERROR "the sim must not call libm's transcendental functions (use sim/core/DetMath.h):\n  ${text}")
endif()
message(STATUS "${LIB}: ${n_undefined} undefined symbols, none of them a libm function outside the exact ones")
