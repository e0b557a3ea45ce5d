// Bring-up top for the iCEBreaker (iCE40 UP5K, docs/boards.md): the CPU with RAM, UART, timer and
// SYSCTRL, without the GPU, which does not fit beside it (the whole SoC is 5,920 LUT4 of the
// UP5K's 5,280 and 48 of its 30 block RAMs). The RAM is 4 KiB of block RAM holding the firmware
// image RamInitFile ($readmemh: `htx image --ram-bytes 4096`); the GPU's addresses answer errors.
// htx_board_reset holds the SoC in reset for its first clocks after configuration and while the
// user button (active low) is pressed.
module htx_icebreaker_top #(
  parameter              RamInitFile = "",
  parameter int unsigned ClockHz     = 12_000_000   // the board's oscillator
) (
  input  logic CLK,
  input  logic BTN_N,    // user button: pressed = 0
  input  logic RX,       // serial from the host (the FTDI)
  output logic TX,       // serial to the host
  output logic LEDR_N,   // red LED, lit = 0: the SoC is in reset
  output logic LEDG_N    // green LED, lit = 0: blinks at about 0.7 Hz while the clock runs
);
  // Reset: 16 clocks after configuration or after the button is released.
  logic rst_n;
  htx_board_reset u_reset (.clk_i(CLK), .button_ni(BTN_N), .rst_no(rst_n));

  logic       timer_irq_unused;
  logic       sim_exit_unused, sim_putchar_unused;
  logic [7:0] sim_code_unused, sim_char_unused;
  logic        video_de_unused, video_hs_unused, video_vs_unused;  // (no GPU, so no picture)
  logic [23:0] video_rgb_unused;

  htx_soc #(
    .RamBytes(4096), .RamInitFile(RamInitFile), .ClockHz(ClockHz), .Sim(1'b0), .StallInject(1'b0),
    .Gpu(1'b0)
  ) u_soc (
    .clk_i(CLK), .rst_ni(rst_n),
    .uart_rx_i(RX), .uart_tx_o(TX),
    .timer_irq_o(timer_irq_unused),
    .sim_exit_o(sim_exit_unused), .sim_exit_code_o(sim_code_unused),
    .sim_putchar_o(sim_putchar_unused), .sim_char_o(sim_char_unused),
    .video_de_o(video_de_unused), .video_hsync_no(video_hs_unused),
    .video_vsync_no(video_vs_unused), .video_rgb_o(video_rgb_unused),
    .stall_en_i(1'b0), .stall_seed_i(32'b0)
  );

  logic [23:0] blink_q = '0;
  always_ff @(posedge CLK) blink_q <= blink_q + 24'd1;
  assign LEDR_N = rst_n;
  assign LEDG_N = !blink_q[23];
endmodule
