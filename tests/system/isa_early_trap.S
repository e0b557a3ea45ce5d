/* For sim_cli_test: an instruction test whose set-up traps before its first test case. The
 * unexpected-trap handler fails the run; before the first case TESTNUM is 0, whose tohost code
 * (0 << 1) | 1 is the pass code, so the failure must be reported under HTX_TEST_BEFORE_FIRST. */
#include "htx_test.h"

TEST_BEGIN
  .word 0                              /* an illegal instruction in the set-up */
  TEST_CASE(1, a0, 5, li a0, 5)
TEST_END
