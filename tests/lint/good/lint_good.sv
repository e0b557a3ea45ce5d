// A clean module: both linters must accept it (the control for the known-bad files beside it).
module lint_good (
  input  logic       clk_i,
  input  logic       rst_ni,
  input  logic [7:0] d_i,
  output logic [7:0] q_o
);
  logic [7:0] q_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) q_q <= '0;
    else         q_q <= d_i;
  end
  assign q_o = q_q;
endmodule
