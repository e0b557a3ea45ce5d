// Comparisons with a constant for the units' address and range checks (docs/area.md, "Synthesis
// idioms").
package htx_cmp_pkg;
  // x < c for a constant c, as a tree of LUTs (first differing bit from the top): Yosys 0.23
  // builds every comparison as a carry chain, a LUT and a carry a bit (32 LUT4 and 23 carries
  // for 24 bits), where this takes about 5 LUT4. For comparisons of two variables the carry
  // chain is the cheaper form; comparisons with zero are sign bits and zero tests (docs/area.md).
  // x and c are unsigned and at most 32 bits (callers widen them with 32'()).
  function automatic logic below_const(input logic [31:0] x, input logic [31:0] c);
    logic lt, eq;
    lt = 1'b0;
    eq = 1'b1;
    for (int i = 31; i >= 0; i--) begin
      lt = lt | (eq & c[i] & ~x[i]);
      eq = eq & (x[i] == c[i]);
    end
    below_const = lt;
  endfunction
endpackage
