// Signed multiplier of the raster setup with a start/done handshake; p_o = (a b) >>> extra_i.
// Iterative = 0: the product (and its shift) is combinational and done_o follows start_i in the
// same cycle (the `full` configuration: one product per clock). Iterative = 1: one bit of b per
// clock, BWidth clocks, then extra_i clocks of right shift in the same registers (the `icebreaker`
// configuration trades clocks for LUTs and DSPs). The operands must stay stable while start_i is held (a_i is
// read on every clock of the product); done_o is a one-cycle pulse. abort_i drops a product in
// progress, so a unit aborted mid-product does not take its stale result for the next one.
module htx_raster_mul #(
  parameter int unsigned AWidth    = 32,
  parameter int unsigned BWidth    = 32,
  parameter bit          Iterative = 1'b0,
  parameter int unsigned ExtraW    = 8
) (
  input  logic                             clk_i,
  input  logic                             rst_ni,
  input  logic                             abort_i,  // drop a product in progress (Iterative)
  input  logic                             start_i,
  input  logic signed [AWidth-1:0]         a_i,
  input  logic signed [BWidth-1:0]         b_i,
  input  logic [ExtraW-1:0]                extra_i,  // p_o = (a b) >>> extra_i
  output logic                             done_o,
  output logic signed [AWidth+BWidth-1:0]  p_o
);
  localparam int unsigned PWidth = AWidth + BWidth;

  if (!Iterative) begin : g_comb
    logic unused;
    logic signed [PWidth-1:0] prod;
    assign unused = ^{clk_i, rst_ni, abort_i};
    assign done_o = start_i;
    assign prod   = PWidth'(a_i) * PWidth'(b_i);
    assign p_o    = prod >>> extra_i;
  end else begin : g_iter
    // The textbook sequential signed multiplier: {h, l} starts as {0, b}; each clock adds a to h
    // when l's lowest bit is set (subtracts it for b's sign bit, the last) and shifts {h, l} right
    // by one, arithmetically. BWidth clocks, one (AWidth + 1)-bit adder, no DSP, no magnitudes.
    // extra_i more clocks go on shifting with nothing added: a right shift of the product for free
    // in the same registers (the plane unit's rounding shift, instead of a barrel shifter).
    localparam int unsigned CntW = $clog2(BWidth + 2**ExtraW);

    logic                     busy_q, done_q, last, in_mul, finish;
    logic [CntW-1:0]          cnt_q;
    logic signed [AWidth:0]   h_q, addend, sum;
    logic [BWidth-1:0]        l_q;

    assign in_mul = (cnt_q < CntW'(BWidth));
    assign last   = (cnt_q == CntW'(BWidth - 1));
    assign finish = (cnt_q == CntW'(BWidth - 1) + CntW'(extra_i));
    assign addend = (l_q[0] && in_mul) ? (AWidth + 1)'(a_i) : '0;
    // h + addend, or h - addend for b's sign bit: one adder (htx_raster_addsub), not two.
    htx_raster_addsub #(.W(AWidth + 1)) u_addsub (
      .a_i(h_q), .b_i(addend), .sub_i(last), .sum_o(sum)
    );

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        busy_q <= 1'b0;
        done_q <= 1'b0;
        cnt_q  <= '0;
        h_q    <= '0;
        l_q    <= '0;
      end else if (abort_i) begin
        busy_q <= 1'b0;
        done_q <= 1'b0;
      end else begin
        done_q <= 1'b0;
        if (!busy_q && !done_q && start_i) begin
          busy_q <= 1'b1;
          cnt_q  <= '0;
          h_q    <= '0;
          l_q    <= b_i;
        end else if (busy_q) begin
          {h_q, l_q} <= {sum[AWidth], sum, l_q[BWidth-1:1]};
          cnt_q      <= cnt_q + 1'b1;
          if (finish) begin
            busy_q <= 1'b0;
            done_q <= 1'b1;
          end
        end
      end
    end

    assign done_o = done_q;
    assign p_o    = {h_q[AWidth-1:0], l_q};
  end
endmodule
