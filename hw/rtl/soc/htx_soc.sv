// The hypertex SoC: the RV32IM core on its instruction and data buses, and the fabric (interconnect,
// RAM, SYSCTRL, UART, TIMER, GPU) behind them. Board tops and the simulation top instantiate this.
module htx_soc #(
  parameter int unsigned RamBytes    = 4096,
  parameter              RamInitFile = "",
  parameter int unsigned ClockHz     = 12_000_000,
  parameter logic [31:0] ResetVector = 32'h0000_0000,
  parameter bit          Sim         = 1'b0,
  parameter bit          StallInject = 1'b0,
  parameter int unsigned FbPixels    = 19200,  // the GPU's framebuffer, 160 x 120
  // The GPU's perspective methods (bit m: htx::Method m): all in simulation, where the firmware's
  // AUTO may choose any; the board's build takes AFFINE and RECIP_LUT (icebreaker-board).
  parameter logic [4:0]  GpuMethods  = 5'b11111,
  // The raster unit's CNT_* counters: built in simulation (the firmware prints raster cycles), left
  // out of the board's build (htx_soc_synth_top; CAPS.COUNTERS tells the firmware).
  parameter bit          GpuCounters = 1'b1,
  // Reads of the texture memory window: built in simulation, left out of the board's build (the
  // firmware only writes texture memory; TEXTURE CAPS.WINDOW_READ tells software).
  parameter bit          GpuTexRead  = 1'b1,
  parameter bit          GpuFbSpram  = 1'b0,  // framebuffer and depth in SPRAM (the board's builds)
  parameter bit          Gpu         = 1'b1   // 0: no GPU (its addresses answer errors; htx_soc_fabric)
) (
  input  logic        clk_i,
  input  logic        rst_ni,

  input  logic        uart_rx_i,
  output logic        uart_tx_o,
  output logic        timer_irq_o,

  output logic        sim_exit_o,
  output logic [7:0]  sim_exit_code_o,
  output logic        sim_putchar_o,
  output logic [7:0]  sim_char_o,

  // The video scan-out, 640x480 at 60 Hz on this clock (htx_video; docs/video.md).
  output logic        video_de_o,
  output logic        video_hsync_no,
  output logic        video_vsync_no,
  output logic [23:0] video_rgb_o,

  input  logic        stall_en_i,
  input  logic [31:0] stall_seed_i
);
  logic        ibus_req_valid, ibus_req_ready, ibus_req_we, ibus_rsp_valid, ibus_rsp_err;
  logic [31:0] ibus_req_addr, ibus_req_wdata, ibus_rsp_rdata;
  logic [3:0]  ibus_req_be;
  logic        dbus_req_valid, dbus_req_ready, dbus_req_we, dbus_rsp_valid, dbus_rsp_err;
  logic [31:0] dbus_req_addr, dbus_req_wdata, dbus_rsp_rdata;
  logic [3:0]  dbus_req_be;

  // The core executes from RAM only (the fabric maps nothing else on its instruction bus), so its
  // executable window is twice the RAM: every fetch outside RAM still faults, by the bus or by
  // the window, and the window's last word is never RAM.
  htx_cpu #(.ResetVector(ResetVector), .PcBits($clog2(RamBytes) + 1)) u_cpu (
    .clk_i, .rst_ni,
    .ibus_req_valid_o(ibus_req_valid), .ibus_req_ready_i(ibus_req_ready),
    .ibus_req_addr_o (ibus_req_addr),  .ibus_req_we_o   (ibus_req_we),
    .ibus_req_be_o   (ibus_req_be),    .ibus_req_wdata_o(ibus_req_wdata),
    .ibus_rsp_valid_i(ibus_rsp_valid), .ibus_rsp_rdata_i(ibus_rsp_rdata),
    .ibus_rsp_err_i  (ibus_rsp_err),
    .dbus_req_valid_o(dbus_req_valid), .dbus_req_ready_i(dbus_req_ready),
    .dbus_req_addr_o (dbus_req_addr),  .dbus_req_we_o   (dbus_req_we),
    .dbus_req_be_o   (dbus_req_be),    .dbus_req_wdata_o(dbus_req_wdata),
    .dbus_rsp_valid_i(dbus_rsp_valid), .dbus_rsp_rdata_i(dbus_rsp_rdata),
    .dbus_rsp_err_i  (dbus_rsp_err)
  );

  htx_soc_fabric #(
    .RamBytes(RamBytes), .RamInitFile(RamInitFile), .ClockHz(ClockHz), .Sim(Sim),
    .StallInject(StallInject), .FbPixels(FbPixels), .GpuMethods(GpuMethods),
    .GpuCounters(GpuCounters), .GpuTexRead(GpuTexRead), .GpuFbSpram(GpuFbSpram), .Gpu(Gpu)
  ) u_fabric (
    .clk_i, .rst_ni,
    .ibus_req_valid_i(ibus_req_valid), .ibus_req_ready_o(ibus_req_ready),
    .ibus_req_addr_i (ibus_req_addr),  .ibus_req_we_i   (ibus_req_we),
    .ibus_req_be_i   (ibus_req_be),    .ibus_req_wdata_i(ibus_req_wdata),
    .ibus_rsp_valid_o(ibus_rsp_valid), .ibus_rsp_rdata_o(ibus_rsp_rdata),
    .ibus_rsp_err_o  (ibus_rsp_err),
    .dbus_req_valid_i(dbus_req_valid), .dbus_req_ready_o(dbus_req_ready),
    .dbus_req_addr_i (dbus_req_addr),  .dbus_req_we_i   (dbus_req_we),
    .dbus_req_be_i   (dbus_req_be),    .dbus_req_wdata_i(dbus_req_wdata),
    .dbus_rsp_valid_o(dbus_rsp_valid), .dbus_rsp_rdata_o(dbus_rsp_rdata),
    .dbus_rsp_err_o  (dbus_rsp_err),
    .uart_rx_i, .uart_tx_o, .timer_irq_o,
    .sim_exit_o, .sim_exit_code_o, .sim_putchar_o, .sim_char_o,
    .video_de_o, .video_hsync_no, .video_vsync_no, .video_rgb_o,
    .stall_en_i, .stall_seed_i
  );
endmodule
