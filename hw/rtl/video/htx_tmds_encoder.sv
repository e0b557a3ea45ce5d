// One TMDS channel of DVI 1.0 (section 3.2.2): a pixel's 8 bits become a 10-bit symbol whose first
// nine bits minimise transitions (an XOR or XNOR chain, bit 8 says which) and whose bit 9 inverts
// the data bits when that keeps the channel's running disparity (ones minus zeros sent) near
// zero. During blanking the two control bits are sent as one of four fixed symbols and the
// disparity restarts at zero. Symbols are sent bit 0 first; one clock of latency.
module htx_tmds_encoder (
  input  logic       clk_i,
  input  logic       rst_ni,
  input  logic       de_i,     // data (1) or control (0) period
  input  logic [7:0] data_i,
  input  logic [1:0] ctrl_i,   // {C1, C0}: on the blue channel {vsync, hsync}
  output logic [9:0] sym_o
);
  function automatic logic [3:0] ones8(input logic [7:0] x);
    ones8 = 4'(x[0]) + 4'(x[1]) + 4'(x[2]) + 4'(x[3]) + 4'(x[4]) + 4'(x[5]) + 4'(x[6]) + 4'(x[7]);
  endfunction

  // Stage 1: transition minimisation.
  function automatic logic [7:0] chain(input logic [7:0] d, input logic xnor_links);
    logic [7:0] q;
    q[0] = d[0];
    for (int i = 1; i < 8; i++) q[i] = xnor_links ? !(q[i-1] ^ d[i]) : (q[i-1] ^ d[i]);
    chain = q;
  endfunction
  logic       use_xnor;
  logic [8:0] qm;
  assign use_xnor = (ones8(data_i) > 4'd4) || ((ones8(data_i) == 4'd4) && !data_i[0]);
  assign qm       = {!use_xnor, chain(data_i, use_xnor)};

  // Stage 2: DC balance. cnt_q is the disparity sent so far (even, |cnt| <= 16 fits 6 bits).
  logic signed [5:0] cnt_q, cnt_d, diff;   // diff = ones - zeros of qm[7:0]
  logic [9:0]        sym_d;
  assign diff = $signed({2'b00, ones8(qm[7:0])}) * 6'sd2 - 6'sd8;
  always_comb begin
    if (!de_i) begin
      cnt_d = '0;
      unique case (ctrl_i)
        2'b00:   sym_d = 10'b1101010100;
        2'b01:   sym_d = 10'b0010101011;
        2'b10:   sym_d = 10'b0101010100;
        default: sym_d = 10'b1010101011;
      endcase
    end else if ((cnt_q == 6'sd0) || (diff == 6'sd0)) begin
      sym_d = {!qm[8], qm[8], qm[8] ? qm[7:0] : ~qm[7:0]};
      cnt_d = qm[8] ? cnt_q + diff : cnt_q - diff;
    end else if ((cnt_q > 6'sd0) == (diff > 6'sd0)) begin
      // The data would move the disparity further from zero: send it inverted.
      sym_d = {1'b1, qm[8], ~qm[7:0]};
      cnt_d = cnt_q + (qm[8] ? 6'sd2 : 6'sd0) - diff;
    end else begin
      sym_d = {1'b0, qm[8], qm[7:0]};
      cnt_d = cnt_q - (qm[8] ? 6'sd0 : 6'sd2) + diff;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      cnt_q <= '0;
      sym_o <= 10'b1101010100;
    end else begin
      cnt_q <= cnt_d;
      sym_o <= sym_d;
    end
  end
endmodule
