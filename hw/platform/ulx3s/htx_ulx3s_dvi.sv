// DVI out of the ULX3S's GPDI connector (an HDMI socket; docs/video.md): the scan-out's pixels as
// three TMDS channels (blue carries the syncs) and the pixel clock as a fourth, each a 10-bit
// symbol a pixel clock, sent bit 0 first at ten times the pixel clock. A toggle of the pixel
// domain, seen through two flip-flops of the 125 MHz domain, loads each channel's shift register
// once a pixel, one or two serial clocks after the symbols changed (the clocks come from one PLL,
// so the phase is fixed); the register then gives two bits a serial clock to an ECP5 DDR output
// (ODDRX1F, bit 0 on the rising edge). Without HTX_ECP5 the outputs carry bit 0 of the shift
// registers (there is no serial clock in simulation; tests check the symbols, sym_o).
module htx_ulx3s_dvi (
  input  logic       clk_pix_i,
  input  logic       rst_pix_ni,
  input  logic       clk_shift_i,
  input  logic       de_i,
  input  logic       hsync_ni,
  input  logic       vsync_ni,
  input  logic [23:0] rgb_i,
  output logic [39:0] sym_o,      // {clock, red, green, blue} symbols of the last pixel clock
  output logic [3:0] gpdi_dp_o     // blue, green, red, clock (the LPF's LVCMOS33D pairs)
);
  logic [9:0] sym_b, sym_g, sym_r;
  // The link carries the sync lines' levels (C0 = HSYNC, C1 = VSYNC on channel 0); 640x480 at
  // 60 Hz has both pulses low, as VESA's timing gives them.
  htx_tmds_encoder u_blue (
    .clk_i(clk_pix_i), .rst_ni(rst_pix_ni), .de_i, .data_i(rgb_i[7:0]),
    .ctrl_i({vsync_ni, hsync_ni}), .sym_o(sym_b)
  );
  htx_tmds_encoder u_green (
    .clk_i(clk_pix_i), .rst_ni(rst_pix_ni), .de_i, .data_i(rgb_i[15:8]), .ctrl_i(2'b00),
    .sym_o(sym_g)
  );
  htx_tmds_encoder u_red (
    .clk_i(clk_pix_i), .rst_ni(rst_pix_ni), .de_i, .data_i(rgb_i[23:16]), .ctrl_i(2'b00),
    .sym_o(sym_r)
  );
  assign sym_o = {10'b0000011111, sym_r, sym_g, sym_b};

  logic toggle_q;
  always_ff @(posedge clk_pix_i or negedge rst_pix_ni) begin
    if (!rst_pix_ni) toggle_q <= 1'b0;
    else             toggle_q <= !toggle_q;
  end

  logic       t1_q, t2_q;
  logic [9:0] sh_q [4];
  always_ff @(posedge clk_shift_i) begin
    t1_q <= toggle_q;
    t2_q <= t1_q;
    for (int l = 0; l < 4; l++) begin
      sh_q[l] <= (t1_q ^ t2_q) ? sym_o[10*l +: 10] : {2'b00, sh_q[l][9:2]};
    end
  end

  for (genvar l = 0; l < 4; l++) begin : g_lane
`ifdef HTX_ECP5
    ODDRX1F u_ddr (.D0(sh_q[l][0]), .D1(sh_q[l][1]), .SCLK(clk_shift_i), .RST(1'b0),
                   .Q(gpdi_dp_o[l]));
`else
    assign gpdi_dp_o[l] = sh_q[l][0];
    logic unused_bit;
    assign unused_bit = sh_q[l][1];
`endif
  end
endmodule
