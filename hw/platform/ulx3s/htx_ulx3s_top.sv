// Board top for the ULX3S (ECP5-85F, docs/boards.md): the SoC exactly as the simulated SoC builds it
// (128 KiB RAM, every perspective method, the raster counters, texture window reads), so a frame
// on the board is the frame `htx sim` draws. The RAM starts with the firmware image RamInitFile
// ($readmemh, one 32-bit word a line: `htx image`). The FPGA's flip-flops start at zero after
// configuration, so a small counter holds the SoC in reset for its first clocks; the PWR button
// (active low) resets it too.
module htx_ulx3s_top #(
  parameter int unsigned RamBytes    = 131072,
  parameter              RamInitFile = "",
  parameter int unsigned ClockHz     = 25_000_000   // the board's oscillator
) (
  input  logic       clk_25mhz,
  input  logic       btn_pwr_n,   // "PWR" button: pressed = 0
  input  logic       ftdi_txd,    // serial from the host (the FTDI's TX)
  output logic       ftdi_rxd,    // serial to the host (the FTDI's RX)
  output logic [7:0] led
);
  logic clk;
  assign clk = clk_25mhz;

  // Power-on reset: 16 clocks after configuration or after the button is released; the button is
  // synchronised first (two flip-flops), the reset is released synchronously.
  logic [1:0] btn_sync_q = 2'b00;
  logic [3:0] por_count_q = 4'd0;
  logic       rst_n_q = 1'b0;
  always_ff @(posedge clk) begin
    btn_sync_q <= {btn_sync_q[0], btn_pwr_n};
    if (!btn_sync_q[1]) begin
      por_count_q <= 4'd0;
      rst_n_q     <= 1'b0;
    end else if (por_count_q != 4'hF) begin
      por_count_q <= por_count_q + 4'd1;
      rst_n_q     <= 1'b0;
    end else begin
      rst_n_q     <= 1'b1;
    end
  end

  logic       timer_irq;
  logic       sim_exit_unused, sim_putchar_unused;
  logic [7:0] sim_code_unused, sim_char_unused;

  htx_soc #(
    .RamBytes(RamBytes), .RamInitFile(RamInitFile), .ClockHz(ClockHz), .Sim(1'b0),
    .StallInject(1'b0)
  ) u_soc (
    .clk_i(clk), .rst_ni(rst_n_q),
    .uart_rx_i(ftdi_txd), .uart_tx_o(ftdi_rxd),
    .timer_irq_o(timer_irq),
    .sim_exit_o(sim_exit_unused), .sim_exit_code_o(sim_code_unused),
    .sim_putchar_o(sim_putchar_unused), .sim_char_o(sim_char_unused),
    .stall_en_i(1'b0), .stall_seed_i(32'b0)
  );

  // LEDs: 0 blinks at about 1.5 Hz while the clock runs (a configured board shows it at once),
  // 1 is the reset, 2 the serial line from the host (lit while idle), 3 the timer's compare.
  logic [23:0] blink_q = '0;
  always_ff @(posedge clk) blink_q <= blink_q + 24'd1;
  assign led = {4'b0000, timer_irq, ftdi_txd, !rst_n_q, blink_q[23]};
endmodule
