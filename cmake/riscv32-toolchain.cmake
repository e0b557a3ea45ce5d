# Cross toolchain for the rv32im soft CPU: Debian's gcc-riscv64-unknown-elf with picolibc.
# -misa-spec=2.2 keeps rdcycle/csrr assembling under plain rv32im (rv32im_zicsr would pick the rv64
# multilib). Linking goes through gcc, not g++ (g++ asks for a libstdc++ that does not exist).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv32)
set(HTX_RISCV_PREFIX riscv64-unknown-elf- CACHE STRING "Cross tool prefix")
set(CMAKE_C_COMPILER ${HTX_RISCV_PREFIX}gcc)
set(CMAKE_CXX_COMPILER ${HTX_RISCV_PREFIX}g++)
set(CMAKE_ASM_COMPILER ${HTX_RISCV_PREFIX}gcc)
set(CMAKE_OBJCOPY ${HTX_RISCV_PREFIX}objcopy CACHE FILEPATH "")
set(CMAKE_SIZE ${HTX_RISCV_PREFIX}size CACHE FILEPATH "")
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(HTX_ARCH_FLAGS "-march=rv32im -misa-spec=2.2 -mabi=ilp32 --specs=picolibc.specs")
set(CMAKE_C_FLAGS_INIT "${HTX_ARCH_FLAGS} -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "${HTX_ARCH_FLAGS} -ffunction-sections -fdata-sections -fno-exceptions -fno-rtti -fno-threadsafe-statics -fno-use-cxa-atexit")
set(CMAKE_ASM_FLAGS_INIT "${HTX_ARCH_FLAGS}")
# CMAKE_CXX_FLAGS already carry the arch flags and specs into the link line (given twice, specs fail).
# Integer-only printf/scanf: the firmware has no floating point to print, and it saves ~6 KiB.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-nostartfiles -Wl,--gc-sections -Wl,--no-warn-rwx-segments -DPICOLIBC_INTEGER_PRINTF_SCANF")
# Link C++ programs with gcc: there is no libstdc++ for this target.
set(CMAKE_CXX_LINK_EXECUTABLE "<CMAKE_C_COMPILER> <FLAGS> <CMAKE_CXX_LINK_FLAGS> <LINK_FLAGS> <OBJECTS> -o <TARGET> <LINK_LIBRARIES>")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
