// Integer ALU: one adder/subtractor (also the load/store address and JALR target adder), a barrel
// shifter (left shifts reuse the right shifter on bit-reversed data) and the branch comparisons.
module htx_cpu_alu (
  input  htx_cpu_pkg::alu_op_e op_i,
  input  logic [31:0]          a_i,
  input  logic [31:0]          b_i,
  output logic [31:0]          result_o,
  output logic [31:0]          sum_o,    // a + b, or a - b for Sub/Slt/Sltu
  output logic                 eq_o,     // a == b
  output logic                 lt_o,     // a < b signed   (valid when op_i subtracts)
  output logic                 ltu_o     // a < b unsigned (valid when op_i subtracts)
);

  logic        sub;
  logic [32:0] sum33;
  assign sub   = (op_i == htx_cpu_pkg::AluSub) || (op_i == htx_cpu_pkg::AluSlt) ||
                 (op_i == htx_cpu_pkg::AluSltu);
  assign sum33 = {1'b0, a_i} + {1'b0, b_i ^ {32{sub}}} + {32'b0, sub};
  assign sum_o = sum33[31:0];
  assign eq_o  = (a_i == b_i);
  assign ltu_o = ~sum33[32];
  assign lt_o  = (a_i[31] != b_i[31]) ? a_i[31] : sum33[31];

  function automatic logic [31:0] reverse32(input logic [31:0] x);
    for (int i = 0; i < 32; i++) begin
      reverse32[i] = x[31-i];
    end
  endfunction

  logic        left;
  logic [31:0] shift_in;
  logic [32:0] shift_ext;
  logic [32:0] shift_r;
  logic [31:0] shift_out;
  assign left      = (op_i == htx_cpu_pkg::AluSll);
  assign shift_in  = left ? reverse32(a_i) : a_i;
  assign shift_ext = {(op_i == htx_cpu_pkg::AluSra) & a_i[31], shift_in};
  assign shift_r   = $unsigned($signed(shift_ext) >>> b_i[4:0]);
  assign shift_out = left ? reverse32(shift_r[31:0]) : shift_r[31:0];

  logic unused_shift_sign;
  assign unused_shift_sign = shift_r[32];  // the sign-fill bit itself is never part of the result

  always_comb begin
    unique case (op_i)
      htx_cpu_pkg::AluAdd,
      htx_cpu_pkg::AluSub:  result_o = sum_o;
      htx_cpu_pkg::AluSlt:  result_o = {31'b0, lt_o};
      htx_cpu_pkg::AluSltu: result_o = {31'b0, ltu_o};
      htx_cpu_pkg::AluXor:  result_o = a_i ^ b_i;
      htx_cpu_pkg::AluOr:   result_o = a_i | b_i;
      htx_cpu_pkg::AluAnd:  result_o = a_i & b_i;
      htx_cpu_pkg::AluSll,
      htx_cpu_pkg::AluSrl,
      htx_cpu_pkg::AluSra:  result_o = shift_out;
      default:              result_o = sum_o;
    endcase
  end

endmodule
