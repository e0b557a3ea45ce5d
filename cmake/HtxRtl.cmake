# RTL helpers: lint tests for every top, and Verilated libraries for the engines and tests.
#
# htx_rtl_top(NAME <top> SOURCES <sv files...> [REGS <peripheral names...>] [YOSYS_ARGS <...>]
#             [YOSYS_ELABORATE])
#   Registers `lint.verilator.<top>` (verilator --lint-only -Wall) and `lint.yosys.<top>` (Debian
#   Yosys 0.23, read_verilog -sv + synth_ice40) with the CTest label `lint`, and records the top's
#   file list in the global properties HTX_RTL_<top>_SOURCES for synthesis reports and Verilation.
#   REGS names the generated register packages (e.g. UART) that the top needs, which come first.
#   YOSYS_ELABORATE: the lint test has Yosys read and elaborate the top (hierarchy -check, proc,
#   flatten, check -assert: any problem `check` reports fails the test) instead of running
#   synth_ice40 on it. For tops that are synthesised whole inside
#   a larger linted top, and for `full` configurations whose synthesis takes minutes; those are
#   synthesised by the `synth-report` target instead (docs/architecture.md, "Lint").
# htx_ice40_equiv(NAME <module> [TEST <test name>] [PARAMS NAME=VALUE...] SOURCES <sv files...>)
#   Registers `lint.ice40_equiv.<test name>` (default: the module): Yosys proves the module's HTX_ICE40 netlist (iCE40 cells
#   from Yosys's own simulation models) equivalent to its behavioural code (equiv_make,
#   equiv_simple, equiv_induct, with the registers' reset made synchronous).
# htx_formal_bmc(NAME <test> TOP <harness> SOURCES <sv files...> DEPTH <cycles>
#                [CUT <modules...>] [COVER <signals...>])
#   Registers the test <test> (label `rtl`): Yosys's SAT solver checks every `assert` of the harness
#   for DEPTH cycles from a free initial state under its `assume`s (`sat -seq -prove-asserts`, a
#   bounded proof). CUT modules have their outputs replaced by free values each cycle (`cutpoint`:
#   an over-approximation, so a proof still holds for the real module). Each COVER signal (a name
#   in the flattened harness) must be reachable within DEPTH: a proof that it stays 0 must fail,
#   so the assertions are not checked on a subset of behaviour that never reaches it.
# htx_verilate(<lib target> TOP <top> [ARGS <verilator args...>] [TRACE])
#   Builds a static library holding the Verilated model of a top registered with htx_rtl_top.

set(HTX_RTL_WAIVERS ${CMAKE_SOURCE_DIR}/hw/rtl/lint.vlt)
# Yosys reads the RTL for the iCE40 with HTX_ICE40 defined: a few modules then instantiate iCE40
# cells where that saves area Yosys does not find itself (docs/architecture.md, "Vendor cells");
# Verilator and every other flow see their behavioural code, which htx_ice40_equiv proves equal.
set(HTX_YOSYS_DEFINES -DHTX_ICE40)
find_program(HTX_VERILATOR_BIN verilator)
find_program(HTX_YOSYS_BIN yosys)

# Source paths made absolute (relative ones are relative to the calling CMakeLists.txt).
function(htx_absolute_paths out)
  set(paths)
  foreach(s IN LISTS ARGN)
    get_filename_component(abs ${s} ABSOLUTE)
    list(APPEND paths ${abs})
  endforeach()
  set(${out} ${paths} PARENT_SCOPE)
endfunction()

function(htx_reg_pkg_files out)
  set(files)
  foreach(p IN LISTS ARGN)
    string(TOLOWER "${p}" lp)
    list(APPEND files ${HTX_GENERATED_RTL}/htx_${lp}_reg_pkg.sv)
  endforeach()
  set(${out} ${files} PARENT_SCOPE)
endfunction()

# The YOSYS_ELABORATE lint flow for `top`, after its sources are read: `check -assert` makes any
# problem `check` finds (a net with several drivers, a driverless used net, a logic loop) fail the
# test. tests/lint runs it on a known-bad module too, so that this flow is seen to fail.
function(htx_yosys_elaborate_flow out top)
  # (iCE40 cells of HTX_ICE40 code as black boxes)
  set(${out} "read_verilog -lib +/ice40/cells_sim.v; hierarchy -check -top ${top}; proc; flatten; opt_clean; check -assert"
    PARENT_SCOPE)
endfunction()

function(htx_rtl_top)
  cmake_parse_arguments(A "YOSYS_ELABORATE" "NAME" "SOURCES;REGS;YOSYS_ARGS" ${ARGN})
  htx_reg_pkg_files(pkgs ${A_REGS})
  htx_absolute_paths(srcs ${A_SOURCES})
  # Packages first: both tools need them before their users.
  set(pkg_srcs ${srcs})
  list(FILTER pkg_srcs INCLUDE REGEX "_pkg\\.sv$")
  set(rest ${srcs})
  list(FILTER rest EXCLUDE REGEX "_pkg\\.sv$")
  set(all ${pkgs} ${pkg_srcs} ${rest})
  set_property(GLOBAL PROPERTY HTX_RTL_${A_NAME}_SOURCES ${all})
  set_property(GLOBAL APPEND PROPERTY HTX_RTL_TOPS ${A_NAME})
  if(HTX_VERILATOR_BIN)
    add_test(NAME lint.verilator.${A_NAME}
      COMMAND ${HTX_VERILATOR_BIN} --lint-only -Wall --top-module ${A_NAME} ${HTX_RTL_WAIVERS} ${all})
    set_tests_properties(lint.verilator.${A_NAME} PROPERTIES LABELS lint)
  endif()
  if(HTX_YOSYS_BIN)
    list(JOIN all " " files)
    if(A_YOSYS_ELABORATE)
      htx_yosys_elaborate_flow(flow ${A_NAME})
    else()
      set(flow "synth_ice40 -dsp -top ${A_NAME} ${A_YOSYS_ARGS}")
    endif()
    add_test(NAME lint.yosys.${A_NAME}
      COMMAND ${HTX_YOSYS_BIN} -q -l ${CMAKE_BINARY_DIR}/lint/${A_NAME}.yosys.log
        -p "read_verilog -sv ${HTX_YOSYS_DEFINES} ${files}; ${flow}")
    set_tests_properties(lint.yosys.${A_NAME} PROPERTIES LABELS lint)
  endif()
  file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/lint)
endfunction()

function(htx_ice40_equiv)
  cmake_parse_arguments(A "" "NAME;TEST" "SOURCES;PARAMS" ${ARGN})
  if(NOT HTX_YOSYS_BIN)
    return()
  endif()
  if(NOT A_TEST)
    set(A_TEST ${A_NAME})
  endif()
  htx_absolute_paths(srcs ${A_SOURCES})
  list(JOIN srcs " " files)
  # PARAMS (NAME=VALUE ...): the parameters both netlists are elaborated with.
  set(top_args)
  foreach(p IN LISTS A_PARAMS)
    string(REPLACE "=" ";" kv ${p})
    list(GET kv 0 k)
    list(GET kv 1 v)
    string(APPEND top_args " -chparam ${k} ${v}")
  endforeach()
  set(script ${CMAKE_BINARY_DIR}/lint/${A_TEST}.ice40_equiv.ys)
  file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/lint)
  file(WRITE ${script}
    "read_verilog -sv ${files}\nhierarchy -top ${A_NAME}${top_args}\nprep -top ${A_NAME}\n"
    "rename ${A_NAME} gold\ndesign -stash gold\n"
    "read_verilog -sv ${HTX_YOSYS_DEFINES} ${files}\nread_verilog -defer +/ice40/cells_sim.v\n"
    "hierarchy -top ${A_NAME}${top_args}\nflatten\nprep -top ${A_NAME}\nrename ${A_NAME} gate\n"
    "design -stash gate\n"
    "design -copy-from gold -as gold gold\ndesign -copy-from gate -as gate gate\n"
    "equiv_make gold gate equiv\nhierarchy -top equiv\nasync2sync\nequiv_simple -seq 2\n"
    "equiv_induct\nequiv_status -assert\n")
  add_test(NAME lint.ice40_equiv.${A_TEST}
    COMMAND ${HTX_YOSYS_BIN} -q -l ${CMAKE_BINARY_DIR}/lint/${A_TEST}.ice40_equiv.log -s ${script})
  set_tests_properties(lint.ice40_equiv.${A_TEST} PROPERTIES LABELS lint)
endfunction()

function(htx_formal_bmc)
  cmake_parse_arguments(A "" "NAME;TOP;DEPTH" "SOURCES;CUT;COVER" ${ARGN})
  if(NOT HTX_YOSYS_BIN)
    return()
  endif()
  htx_absolute_paths(srcs ${A_SOURCES})
  list(JOIN srcs " " files)
  set(script ${CMAKE_BINARY_DIR}/formal/${A_NAME}.ys)
  file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/formal)
  set(text "read_verilog -sv -formal ${files}\nprep -top ${A_TOP}\n")
  if(A_CUT)
    list(JOIN A_CUT " " cut)
    string(APPEND text "cutpoint ${cut}\n")
  endif()
  # The register file and buffers become flip-flops (the SAT pass takes no memories); reset
  # becomes synchronous with its value visible at once, as the asynchronous one is.
  string(APPEND text "memory_map\nflatten\nopt -fast\nasync2sync\ndffunmap\nopt_clean\n")
  foreach(c IN LISTS A_COVER)
    string(APPEND text "sat -seq ${A_DEPTH} -set-assumes -prove ${c} 0 -falsify -timeout 900\n")
  endforeach()
  string(APPEND text "sat -seq ${A_DEPTH} -set-assumes -prove-asserts -verify -show-ports -timeout 900"
    " -dump_vcd ${CMAKE_BINARY_DIR}/formal/${A_NAME}.vcd\n")
  file(WRITE ${script} "${text}")
  add_test(NAME ${A_NAME}
    COMMAND ${HTX_YOSYS_BIN} -q -l ${CMAKE_BINARY_DIR}/formal/${A_NAME}.log -s ${script})
  set_tests_properties(${A_NAME} PROPERTIES LABELS rtl TIMEOUT 1200)
endfunction()

# PREFIX names the generated class (default V<TOP>), so two parameterisations of one top can be
# linked into one test.
function(htx_verilate lib)
  cmake_parse_arguments(A "TRACE" "TOP;PREFIX" "ARGS" ${ARGN})
  if(NOT A_PREFIX)
    set(A_PREFIX V${A_TOP})
  endif()
  get_property(all GLOBAL PROPERTY HTX_RTL_${A_TOP}_SOURCES)
  if(NOT all)
    message(FATAL_ERROR "htx_verilate: ${A_TOP} was not registered with htx_rtl_top")
  endif()
  add_library(${lib} STATIC)
  set(trace)
  if(A_TRACE)
    set(trace TRACE_FST)
  endif()
  verilate(${lib} SOURCES ${HTX_RTL_WAIVERS} ${all} TOP_MODULE ${A_TOP} PREFIX ${A_PREFIX} ${trace}
    VERILATOR_ARGS -O3 -Wno-fatal --x-assign fast --x-initial fast ${A_ARGS})
  add_dependencies(${lib} htx_regs_sv)
  target_compile_options(${lib} PRIVATE -O2 -w)
endfunction()

# htx_board_top(<board> <top> <sv file>...): a board's top over the whole SoC (hw/platform/<board>,
# docs/boards.md). Registers it with htx_rtl_top (lint; the SoC's sources and the boards' reset),
# Verilates it as htx_<board>_model when HTX_BUILD_RTL is on (its RAM image is board_ram.hex in the
# working directory, read when the model starts, so each test chooses its firmware by writing it),
# and sets <top>_SOURCES_ARG, its sources joined with |, for the board's build script (cmake -P).
function(htx_board_top board top)
  htx_rtl_top(NAME ${top} REGS ${HTX_SOC_REGS}
    SOURCES ${HTX_SOC_SOURCES} ${CMAKE_SOURCE_DIR}/hw/rtl/lib/htx_board_reset.sv ${ARGN} YOSYS_ELABORATE)
  if(HTX_BUILD_RTL)
    htx_verilate(htx_${board}_model TOP ${top} PREFIX V${top} ARGS "-GRamInitFile=\"board_ram.hex\"")
  endif()
  get_property(sources GLOBAL PROPERTY HTX_RTL_${top}_SOURCES)
  list(JOIN sources "|" joined)
  set(${top}_SOURCES_ARG "${joined}" PARENT_SCOPE)
endfunction()
