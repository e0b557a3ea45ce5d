// Board top for the ULX3S (ECP5-85F, docs/boards.md): the SoC exactly as the simulated SoC builds it
// (128 KiB RAM, every perspective method, the raster counters, texture window reads), so a frame
// on the board is the frame `htx sim` draws. The RAM starts with the firmware image RamInitFile
// ($readmemh, one 32-bit word a line: `htx image`). htx_board_reset holds the SoC in reset for its
// first clocks after configuration, until the PLL locks, and while the PWR button (active low) is
// pressed. The scan-out (VIDEO) goes to the GPDI (HDMI) connector as DVI, 640x480 at 60 Hz.
module htx_ulx3s_top #(
  parameter int unsigned RamBytes    = 131072,
  parameter              RamInitFile = "",
  parameter int unsigned ClockHz     = 25_000_000   // the board's oscillator
) (
  input  logic       clk_25mhz,
  input  logic       btn_pwr_n,   // "PWR" button: pressed = 0
  input  logic       ftdi_txd,    // serial from the host (the FTDI's TX)
  output logic       ftdi_rxd,    // serial to the host (the FTDI's RX)
  output logic [7:0] led,
  output logic [3:0] gpdi_dp,     // DVI: blue, green, red, clock (LVCMOS33D pairs)
  output logic       wifi_gpio0   // the ESP32's GPIO0, held high (low at its reset: its bootloader)
);
  assign wifi_gpio0 = 1'b1;

  logic clk, clk_shift, locked;
  htx_ulx3s_clocks u_clocks (
    .clk_25mhz_i(clk_25mhz), .clk_sys_o(clk), .clk_shift_o(clk_shift), .locked_o(locked)
  );

  // Reset: 16 clocks after configuration, the PLL's lock or the button's release.
  logic rst_n;
  htx_board_reset u_reset (.clk_i(clk), .button_ni(btn_pwr_n && locked), .rst_no(rst_n));

  logic       timer_irq;
  logic       sim_exit_unused, sim_putchar_unused;
  logic [7:0] sim_code_unused, sim_char_unused;
  logic        video_de, video_hsync_n, video_vsync_n;
  logic [23:0] video_rgb;

  htx_soc #(
    .RamBytes(RamBytes), .RamInitFile(RamInitFile), .ClockHz(ClockHz), .Sim(1'b0),
    .StallInject(1'b0)
  ) u_soc (
    .clk_i(clk), .rst_ni(rst_n),
    .uart_rx_i(ftdi_txd), .uart_tx_o(ftdi_rxd),
    .timer_irq_o(timer_irq),
    .sim_exit_o(sim_exit_unused), .sim_exit_code_o(sim_code_unused),
    .sim_putchar_o(sim_putchar_unused), .sim_char_o(sim_char_unused),
    .video_de_o(video_de), .video_hsync_no(video_hsync_n), .video_vsync_no(video_vsync_n),
    .video_rgb_o(video_rgb),
    .stall_en_i(1'b0), .stall_seed_i(32'b0)
  );

  logic [39:0] dvi_symbols /* verilator public_flat_rd */;  // (the board test decodes these)
  htx_ulx3s_dvi u_dvi (
    .clk_pix_i(clk), .rst_pix_ni(rst_n), .clk_shift_i(clk_shift),
    .de_i(video_de), .hsync_ni(video_hsync_n), .vsync_ni(video_vsync_n), .rgb_i(video_rgb),
    .sym_o(dvi_symbols), .gpdi_dp_o(gpdi_dp)
  );

  // LEDs: 0 blinks at about 1.5 Hz while the clock runs (a configured board shows it at once),
  // 1 is the reset, 2 the serial line from the host (lit while idle), 3 the timer's compare.
  logic [23:0] blink_q = '0;
  always_ff @(posedge clk) blink_q <= blink_q + 24'd1;
  assign led = {4'b0000, timer_irq, ftdi_txd, !rst_n, blink_q[23]};
endmodule
