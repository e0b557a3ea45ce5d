// Known-bad for the Yosys elaborate lint (cmake/HtxRtl.cmake, YOSYS_ELABORATE): `y_o` has two drivers,
// which Yosys's `check` reports; with `check -assert` the lint must fail on it.
module lint_bad_multidriven (
  input  logic a_i,
  input  logic b_i,
  output logic y_o
);
  assign y_o = a_i;
  assign y_o = b_i;
endmodule
