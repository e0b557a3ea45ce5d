# The RV32IM instruction tests: tests/rtl/isa/<name>.S, each a self-checking program that ends
# through `tohost` and SYSCTRL SIM_EXIT (see htx_test.h). Included by tests/rtl/cpu and usable by
# the firmware build or `htx sim` tests.
set(HTX_ISA_TESTS
  alu
  shift
  lui_auipc
  branch
  jump
  load
  store
  mul
  mulfuse
  div
  csr
  counters
  traps
  window
  hazards
  fence)
set(HTX_ISA_TEST_DIR ${CMAKE_CURRENT_LIST_DIR})
