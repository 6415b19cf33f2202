# Instruments everything built after it for libFuzzer (coverage) and with AddressSanitizer and
# UndefinedBehaviorSanitizer; the fuzz targets in test/fuzz add libFuzzer's main. OpenCV itself
# stays Debian's uninstrumented gcc build, which links fine with clang objects.
if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "TRIPOSE_BUILD_FUZZERS needs clang with libFuzzer "
                      "(e.g. -DCMAKE_CXX_COMPILER=clang++-14; Debian: clang-14 libclang-rt-14-dev)")
endif()
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                    -fno-omit-frame-pointer -gline-tables-only)
add_link_options(-fsanitize=address,undefined)
