# Instrumented builds, each in a build directory of its own (scripts/test.sh --sanitize=...,
# scripts/fuzz.sh): every target of the tree is compiled with the same flags, so that the
# sanitizers see libmaquette, the formats and the modules, not only the executables.
set(MAQUETTE_SANITIZE "" CACHE STRING
    "Sanitizers: address (AddressSanitizer + UndefinedBehaviorSanitizer) or thread")
option(MAQUETTE_FUZZ "Build the libFuzzer targets of fuzz/ (clang only, with ASan + UBSan)" OFF)

if(MAQUETTE_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "MAQUETTE_FUZZ needs clang (libFuzzer): -DCMAKE_CXX_COMPILER=clang++")
  endif()
  # fuzzer-no-link: coverage for the fuzzer everywhere; only fuzz/'s executables link its main.
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
                      -fno-omit-frame-pointer -g)
  add_link_options(-fsanitize=address,undefined)
elseif(MAQUETTE_SANITIZE STREQUAL "address")
  # An undefined behaviour stops the program (a test fails) rather than printing and going on.
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
elseif(MAQUETTE_SANITIZE STREQUAL "thread")
  add_compile_options(-fsanitize=thread)
  add_link_options(-fsanitize=thread)
elseif(NOT MAQUETTE_SANITIZE STREQUAL "")
  message(FATAL_ERROR "MAQUETTE_SANITIZE=${MAQUETTE_SANITIZE}: expected address or thread")
endif()
