// Signed multiplier of the raster setup with a start/done handshake. Iterative = 0: the product is
// combinational and done_o follows start_i in the same cycle (the `full` configuration: one product
// per clock). Iterative = 1: a shift-and-add unit that retires StepBits bits of b per clock on the
// magnitudes and fixes the sign at the end (the `icebreaker` configuration trades clocks for LUTs).
// The operands must stay stable while start_i is held; done_o is a one-cycle pulse.
module htx_raster_mul #(
  parameter int unsigned AWidth    = 32,
  parameter int unsigned BWidth    = 32,
  parameter bit          Iterative = 1'b0,
  parameter int unsigned StepBits  = 4
) (
  input  logic                             clk_i,
  input  logic                             rst_ni,
  input  logic                             start_i,
  input  logic signed [AWidth-1:0]         a_i,
  input  logic signed [BWidth-1:0]         b_i,
  output logic                             done_o,
  output logic signed [AWidth+BWidth-1:0]  p_o
);
  localparam int unsigned PWidth = AWidth + BWidth;

  if (!Iterative) begin : g_comb
    logic unused;
    assign unused = ^{clk_i, rst_ni};
    assign done_o = start_i;
    assign p_o    = PWidth'(a_i) * PWidth'(b_i);
  end else begin : g_iter
    localparam int unsigned Steps  = (BWidth + StepBits - 1) / StepBits;
    localparam int unsigned BPad   = Steps * StepBits;
    localparam int unsigned CntW   = $clog2(Steps + 1);

    logic              busy_q, done_q, neg_q;
    logic [CntW-1:0]   cnt_q;
    logic [PWidth-1:0] acc_q, mag_a_q;
    logic [BPad-1:0]   mag_b_q;
    logic [AWidth-1:0] abs_a;
    logic [BWidth-1:0] abs_b;
    logic [PWidth-1:0] partial;

    assign abs_a = a_i[AWidth-1] ? AWidth'(-a_i) : a_i;
    assign abs_b = b_i[BWidth-1] ? BWidth'(-b_i) : b_i;
    // Partial product of b's lowest StepBits with a; a shifts left as b's bits retire.
    assign partial = mag_a_q * PWidth'(mag_b_q[StepBits-1:0]);

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        busy_q  <= 1'b0;
        done_q  <= 1'b0;
        neg_q   <= 1'b0;
        cnt_q   <= '0;
        acc_q   <= '0;
        mag_a_q <= '0;
        mag_b_q <= '0;
      end else begin
        done_q <= 1'b0;
        if (!busy_q && !done_q && start_i) begin
          busy_q  <= 1'b1;
          neg_q   <= a_i[AWidth-1] ^ b_i[BWidth-1];
          mag_a_q <= PWidth'(abs_a);
          mag_b_q <= BPad'(abs_b);
          acc_q   <= '0;
          cnt_q   <= '0;
        end else if (busy_q) begin
          acc_q   <= acc_q + partial;
          mag_a_q <= mag_a_q << StepBits;
          mag_b_q <= mag_b_q >> StepBits;
          cnt_q   <= cnt_q + 1'b1;
          if (cnt_q == CntW'(Steps - 1)) begin
            busy_q <= 1'b0;
            done_q <= 1'b1;
          end
        end
      end
    end

    assign done_o = done_q;
    assign p_o    = neg_q ? -acc_q : acc_q;
  end
endmodule
