// Integer ALU: one adder/subtractor (also the load/store address and JALR target adder), logic
// operations, the branch comparisons, set-less-than and a barrel shifter (left shifts reuse the
// right shifter on bit-reversed data). The results are split by when they are ready: fast_o (add,
// sub, xor, or, and) is forwarded from E into D, late_o (shifts) and lt_o (slt, sltu) only from W
// (lt_o comes from the end of the carry chain). For a left
// shift late_o is still bit-reversed: write-back puts it in order, which keeps a LUT level out of E.
//
// For a subtraction or comparison (sub_i) the operand b_i arrives already inverted (decode does it
// together with the operand select), which keeps one LUT level off the carry chain's input. The
// adder is 33 bits wide: decode extends the operands with their sign bits for a signed comparison
// and with zeros for an unsigned one, so bit 32 of a - b is the comparison result straight from
// the end of the carry chain.
//
// invert_i inverts the sum (a MUL-class instruction: the multiplier's DSP adds ~(a + b), the
// signed correction, docs/cpu.md). It costs no LUT: each sum bit's iCE40 carry-chain LUT computes
// a ^ b ^ carry from three of its four inputs, and the fourth takes invert_i. With HTX_ICE40 the
// adder is written as those cells (SB_LUT4 and SB_CARRY a bit); Yosys maps the behavioural code
// with a LUT more a bit for the inversion (docs/architecture.md, "Vendor cells").
module htx_cpu_alu (
  input  htx_cpu_pkg::alu_op_e op_i,
  input  logic                 sub_i,    // op_i is Sub, Slt or Sltu (decoded a cycle earlier)
  input  logic                 left_i,   // op_i is Sll (decoded a cycle earlier)
  input  logic                 arith_i,  // op_i is Sra (decoded a cycle earlier)
  input  logic                 invert_i, // sum_o (and the sum behind eq_o, lt_o, fast_o) inverted
  input  logic [32:0]          a_i,      // bit 32: extension for comparisons
  input  logic [32:0]          b_i,      // b, or ~b when sub_i; bit 32 likewise
  output logic [31:0]          fast_o,   // add, sub, xor, or, and
  output logic [31:0]          late_o,   // sll (bit-reversed), srl, sra
  output logic [31:0]          sum_o,    // a + b, or a - b when sub_i; inverted when invert_i
  output logic                 eq_o,     // a == b (valid when sub_i: a - b is 0)
  output logic                 lt_o      // a < b, signed or not as extended (valid when sub_i)
);

  logic [32:0] sum33;
`ifdef HTX_ICE40
  logic [32:0] carry;
  assign carry[0] = sub_i;
  for (genvar i = 0; i < 33; i++) begin : g_bit
    // O = I0 ^ I1 ^ I2 ^ I3  (I0 invert, I1 a, I2 b, I3 carry in)
    SB_LUT4 #(.LUT_INIT(16'h6996)) u_sum_lut (
      .O(sum33[i]), .I0(invert_i), .I1(a_i[i]), .I2(b_i[i]), .I3(carry[i]));
    if (i < 32) begin : g_carry
      SB_CARRY u_sum_carry (.CO(carry[i+1]), .I0(a_i[i]), .I1(b_i[i]), .CI(carry[i]));
    end
  end
`else
  assign sum33 = (a_i + b_i + {32'b0, sub_i}) ^ {33{invert_i}};
`endif
  assign sum_o = sum33[31:0];
  // Equality from the difference (branches always subtract): a zero test of the sum is about 20
  // LUT4 smaller than comparing the operands bit by bit. The carry chain's low sum bits settle
  // first, so they are tested on their own (kept) and only the top twelve after the chain's end:
  // one balanced tree put three LUT levels between the chain and the branch condition (29.1 MHz
  // at two of three seeds). The low test is two kept halves: as one signal ABC made it a chain of
  // four LUTs fed from bit 19, which became the critical path (2026-12-07, thirty-sixth session).
  (* keep *) logic eq_low, eq_low_a, eq_low_b;
  assign eq_low_a = (sum33[9:0] == 10'b0);
  assign eq_low_b = (sum33[19:10] == 10'b0);
  assign eq_low   = eq_low_a && eq_low_b;
  assign eq_o   = eq_low && (sum33[31:20] == 12'b0);
  assign lt_o  = sum33[32];

  // The logic result is kept as a signal of its own (one LUT4 a bit from the operands, beside the
  // carry chain), so that only its choice against the sum folds into the forwarding multiplexers
  // that use fast_o: folding the whole operation into each of them cost 29 LUT4 more.
  (* keep *) logic [31:0] logic_r;
  logic                   is_logic;
  always_comb begin
    unique case (op_i)
      htx_cpu_pkg::AluXor: logic_r = a_i[31:0] ^ b_i[31:0];
      htx_cpu_pkg::AluOr:  logic_r = a_i[31:0] | b_i[31:0];
      default:             logic_r = a_i[31:0] & b_i[31:0];
    endcase
  end
  assign is_logic = (op_i == htx_cpu_pkg::AluXor) || (op_i == htx_cpu_pkg::AluOr) ||
                    (op_i == htx_cpu_pkg::AluAnd);
  assign fast_o   = is_logic ? logic_r : sum_o;

  function automatic logic [31:0] reverse32(input logic [31:0] x);
    for (int i = 0; i < 32; i++) begin
      reverse32[i] = x[31-i];
    end
  endfunction

  logic [31:0] shift_in;
  logic [32:0] shift_ext;
  logic [32:0] shift_r;
  assign shift_in  = left_i ? reverse32(a_i[31:0]) : a_i[31:0];
  assign shift_ext = {arith_i & a_i[31], shift_in};
  assign shift_r   = $unsigned($signed(shift_ext) >>> b_i[4:0]);

  logic unused_shift_sign;
  assign unused_shift_sign = shift_r[32];  // the sign-fill bit itself is never part of the result
  logic unused_b_high;
  assign unused_b_high = ^b_i[32:5];       // shift amounts use b_i[4:0] only

  assign late_o = shift_r[31:0];

endmodule
