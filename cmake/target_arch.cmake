# sluice_target_arch(TARGET ARCH): compiles TARGET's users with -march=ARCH on x86-64, after
# checking that this machine can run such code (the tests run here). A machine that cannot
# (an x86-64-v3 build on a CPU without AVX2) gets the compiler's default, with a warning.
function(sluice_target_arch target arch)
  if(arch STREQUAL "" OR NOT CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64)$")
    message(STATUS "sluice: compiler's default instruction set")
    return()
  endif()
  if(NOT arch STREQUAL "native")
    set(probe "${CMAKE_BINARY_DIR}/arch_probe.cpp")
    file(WRITE "${probe}" "int main() { return __builtin_cpu_supports(\"${arch}\") ? 0 : 1; }\n")
    try_run(runs compiles "${CMAKE_BINARY_DIR}/arch_probe" "${probe}"
            COMPILE_OUTPUT_VARIABLE compile_output)
    if(NOT compiles OR NOT runs EQUAL 0)
      message(WARNING "sluice: this CPU cannot run ${arch} code (or the compiler cannot ask): "
                      "building for the compiler's default instead; results may differ in the "
                      "last bits from ${arch} builds")
      return()
    endif()
  endif()
  message(STATUS "sluice: building for -march=${arch}")
  target_compile_options(${target} INTERFACE $<$<COMPILE_LANGUAGE:C,CXX>:-march=${arch}>
                                             $<$<COMPILE_LANGUAGE:CUDA>:-Xcompiler=-march=${arch}>)
endfunction()
