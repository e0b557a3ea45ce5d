# The rv32im firmware is a separate CMake project (firmware/) cross-compiled in the same configure
# through ExternalProject. It needs the generated register header, so it runs after htx_regs_c.
include(ExternalProject)
find_program(HTX_RISCV_GCC riscv64-unknown-elf-gcc)
if(NOT HTX_RISCV_GCC)
  message(FATAL_ERROR "riscv64-unknown-elf-gcc not found: run scripts/bootstrap, or configure with -DHTX_BUILD_FIRMWARE=OFF")
endif()
set(HTX_FIRMWARE_DIR ${CMAKE_BINARY_DIR}/firmware/bin CACHE INTERNAL "Where the firmware ELFs land")
ExternalProject_Add(firmware
  SOURCE_DIR ${CMAKE_SOURCE_DIR}/firmware
  # Not BUILD/firmware: the host build of firmware/lib already lives in BUILD/firmware/lib.
  BINARY_DIR ${CMAKE_BINARY_DIR}/firmware-rv32
  CMAKE_ARGS
    -G Ninja
    -DCMAKE_TOOLCHAIN_FILE=${CMAKE_SOURCE_DIR}/cmake/riscv32-toolchain.cmake
    -DCMAKE_BUILD_TYPE=MinSizeRel
    -DHTX_SOURCE_ROOT=${CMAKE_SOURCE_DIR}
    -DHTX_GENERATED_INCLUDE=${HTX_GENERATED_INCLUDE}
    -DHTX_FIRMWARE_BIN=${HTX_FIRMWARE_DIR}
    $<$<BOOL:${CCACHE_PROGRAM}>:-DCMAKE_C_COMPILER_LAUNCHER=${CCACHE_PROGRAM}>
    $<$<BOOL:${CCACHE_PROGRAM}>:-DCMAKE_CXX_COMPILER_LAUNCHER=${CCACHE_PROGRAM}>
  INSTALL_COMMAND ""
  BUILD_ALWAYS ON
  USES_TERMINAL_BUILD ON
  DEPENDS htx_regs_c)
