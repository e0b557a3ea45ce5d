# Warnings for host code written in this project (not applied to Verilator's generated C++).
add_library(htx_warnings INTERFACE)
target_compile_options(htx_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wno-unused-parameter)
