// htx_fb_ram in the two shapes the board's framebuffer uses, built from SPRAM (Verilated with
// HTX_ICE40 and the model of SB_SPRAM256KA): colour, two 16-bit lanes of 9,600 words (one block
// per lane), and depth, one lane of 19,200 words (two blocks stacked by address).
module htx_fb_ram_tb (
  input  logic        clk_i,
  input  logic        re_i,
  input  logic [14:0] raddr_i,
  input  logic [1:0]  we_i,
  input  logic [14:0] waddr_i,
  input  logic [31:0] wdata_i,
  output logic [31:0] color_rdata_o,
  output logic [15:0] depth_rdata_o
);
  htx_fb_ram #(.LaneW(16), .Lanes(2), .Words(9600), .Spram(1'b1)) u_color (
    .clk_i, .re_i, .raddr_i(raddr_i[13:0]), .rdata_o(color_rdata_o), .we_i,
    .waddr_i(waddr_i[13:0]), .wdata_i
  );
  htx_fb_ram #(.LaneW(16), .Lanes(1), .Words(19200), .Spram(1'b1)) u_depth (
    .clk_i, .re_i, .raddr_i, .rdata_o(depth_rdata_o), .we_i(we_i[0]), .waddr_i,
    .wdata_i(wdata_i[15:0])
  );
endmodule
