// Synthesis harness for soc_up5k in the synthesis report: the SoC as a board would have it (no
// simulation ports, no stall injection, the board GPU's methods AFFINE and RECIP_LUT and no raster
// event counters, as gpu_icebreaker_up5k), with only the clock, reset, serial and video pins at the
// package (the video as the iCEBreaker's 12-bit DVI Pmod takes it: four bits a colour).
module htx_soc_synth_top #(
  parameter int unsigned RamBytes = 4096
) (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic uart_rx_i,
  output logic uart_tx_o,
  output logic timer_irq_o,
  output logic video_de_o,
  output logic video_hsync_no,
  output logic video_vsync_no,
  output logic [11:0] video_rgb444_o
);
  logic [23:0] rgb;
  assign video_rgb444_o = {rgb[23:20], rgb[15:12], rgb[7:4]};
  logic unused_rgb;
  assign unused_rgb = ^{rgb[19:16], rgb[11:8], rgb[3:0]};
  logic       sim_exit_unused, sim_putchar_unused;
  logic [7:0] sim_code_unused, sim_char_unused;

  htx_soc #(.RamBytes(RamBytes), .Sim(1'b0), .StallInject(1'b0), .GpuMethods(htx_raster_pkg::board_methods()),
    .GpuCounters(1'b0), .GpuTexRead(1'b0), .GpuFbSpram(1'b1)) u_soc (
    .clk_i, .rst_ni, .uart_rx_i, .uart_tx_o, .timer_irq_o,
    .sim_exit_o(sim_exit_unused), .sim_exit_code_o(sim_code_unused),
    .sim_putchar_o(sim_putchar_unused), .sim_char_o(sim_char_unused),
    .video_de_o, .video_hsync_no, .video_vsync_no, .video_rgb_o(rgb),
    .stall_en_i(1'b0), .stall_seed_i(32'b0)
  );
endmodule
