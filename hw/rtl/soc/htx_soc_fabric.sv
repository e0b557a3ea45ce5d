// Everything of the SoC except the CPU: the interconnect, the RAM, the peripherals and the GPU, with
// the two CPU bus ports (instruction, data) as slave ports. Tests drive these ports directly; htx_soc
// puts the CPU on them.
//
//   ibus -> demux --RAM port A
//   dbus -> demux --RAM port B
//                 |-IO demux -> SYSCTRL, UART, TIMER, RASTER + TEXTURE -> GPU reg, VIDEO
//                 \-framebuffer/depth window + texture window ---------> GPU mem
//
// Code runs from RAM only: the register blocks (0x2xxx_xxxx) and the GPU's memory windows are on the
// data port alone, and an instruction fetch from them answers rsp_err (there is no code there). So
// the IO path has one master and no arbiter, and the fetch path only the RAM. The RAM is
// dual-ported, so fetch and data never wait for each other. Each demux answers addresses no slave
// claims with rsp_err. With StallInject, every slave sits behind an htx_bus_stall whose random wait states
// are switched on by stall_en_i.
//
// The GPU is htx_gpu_icebreaker (docs/soc.md, "GPU"): raster and texture units in the `icebreaker`
// configuration of the UP5K board, with framebuffer and depth memories of FbPixels pixels (three
// colour pages of them, except in SPRAM). Its two
// register blocks and its memory windows are each claimed by their own demux entry (so every other
// address answers an error here) and joined onto the GPU's two ports: a demux sends requests to one
// target at a time and takes responses only from that target, so two windows of one slave can share
// its link (valid ORed, ready and response fanned out).
module htx_soc_fabric #(
  parameter int unsigned RamBytes    = 4096,
  parameter              RamInitFile = "",
  parameter int unsigned ClockHz     = 12_000_000,
  parameter bit          Sim         = 1'b0,
  parameter bit          StallInject = 1'b0,
  parameter int unsigned FbPixels    = 19200,  // 160 x 120, even
  parameter logic [4:0]  GpuMethods  = 5'b11111, // bit m: htx::Method m built (htx_soc)
  parameter bit          GpuCounters = 1'b1,     // the raster unit's CNT_* (CAPS.COUNTERS)
  parameter bit          GpuTexRead  = 1'b1,     // texture window reads (TEXTURE CAPS.WINDOW_READ)
  parameter bit          GpuFbSpram  = 1'b0,     // framebuffer and depth in SPRAM (the board's builds)
  // 0: no GPU (a board the SoC does not fit whole: the iCEBreaker's bring-up build). The demuxes then
  // claim none of its register blocks and memory windows, which answer rsp_err like unmapped addresses.
  parameter bit          Gpu         = 1'b1
) (
  input  logic        clk_i,
  input  logic        rst_ni,

  input  logic        ibus_req_valid_i,
  output logic        ibus_req_ready_o,
  input  logic [31:0] ibus_req_addr_i,
  input  logic        ibus_req_we_i,
  input  logic [3:0]  ibus_req_be_i,
  input  logic [31:0] ibus_req_wdata_i,
  output logic        ibus_rsp_valid_o,
  output logic [31:0] ibus_rsp_rdata_o,
  output logic        ibus_rsp_err_o,

  input  logic        dbus_req_valid_i,
  output logic        dbus_req_ready_o,
  input  logic [31:0] dbus_req_addr_i,
  input  logic        dbus_req_we_i,
  input  logic [3:0]  dbus_req_be_i,
  input  logic [31:0] dbus_req_wdata_i,
  output logic        dbus_rsp_valid_o,
  output logic [31:0] dbus_rsp_rdata_o,
  output logic        dbus_rsp_err_o,

  input  logic        uart_rx_i,
  output logic        uart_tx_o,
  output logic        timer_irq_o,

  output logic        sim_exit_o,
  output logic [7:0]  sim_exit_code_o,
  output logic        sim_putchar_o,
  output logic [7:0]  sim_char_o,

  // The video scan-out (htx_video; with Gpu = 0 there is none: de 0, syncs idle).
  output logic        video_de_o,
  output logic        video_hsync_no,
  output logic        video_vsync_no,
  output logic [23:0] video_rgb_o,

  input  logic        stall_en_i,
  input  logic [31:0] stall_seed_i
);
  // Three colour pages (triple buffering, docs/video.md) where the memories are block RAM; the
  // UP5K's SPRAM holds one page beside the depth buffer.
  localparam int unsigned FbPages = GpuFbSpram ? 1 : 3;
  localparam logic [31:0] RamBase = 32'h0000_0000;
  localparam logic [31:0] RamMask = ~(32'(RamBytes) - 32'd1);
  localparam logic [31:0] IoBase  = 32'h2000_0000;
  localparam logic [31:0] IoMask  = 32'hF000_0000;
  localparam logic [31:0] RegMask = 32'hFFFF_F000;  // 4 KiB register blocks
  localparam int unsigned NumIo   = 6;          // SYSCTRL, UART, TIMER, RASTER, TEXTURE, VIDEO
  localparam int unsigned NumLink = 5;          // SYSCTRL, UART, TIMER, GPU registers, VIDEO
  localparam logic [31:0] FbBase  = 32'h3000_0000;  // colour 0x3000_0000, depth 0x3010_0000
  localparam logic [31:0] FbMask  = 32'hFFE0_0000;
  localparam logic [31:0] TexBase = 32'h4000_0000;  // texture memory, 1 MiB
  localparam logic [31:0] TexMask = 32'hFFF0_0000;

  // ---- CPU-side demuxes: ibus slave 0 = RAM port A; dbus slave 0 = RAM port B, 1 = IO demux,
  // 2 and 3 = the GPU's memory windows (framebuffer/depth, texture) ----
  logic [0:0]  i_valid, i_ready, i_rsp_valid, i_rsp_err;
  logic [31:0] i_addr, i_wdata;
  logic        i_we;
  logic [3:0]  i_be;
  logic [31:0] i_rsp_rdata;
  logic [3:0]   d_valid, d_ready, d_rsp_valid, d_rsp_err;
  logic [31:0]  d_addr, d_wdata;
  logic         d_we;
  logic [3:0]   d_be;
  logic [127:0] d_rsp_rdata;

  htx_bus_demux #(
    .NumSlaves(1),
    .SlaveBase(RamBase),
    .SlaveMask(RamMask)
  ) u_ibus_demux (
    .clk_i, .rst_ni,
    .m_req_valid_i(ibus_req_valid_i), .m_req_ready_o(ibus_req_ready_o),
    .m_req_addr_i (ibus_req_addr_i),  .m_req_we_i   (ibus_req_we_i),
    .m_req_be_i   (ibus_req_be_i),    .m_req_wdata_i(ibus_req_wdata_i),
    .m_rsp_valid_o(ibus_rsp_valid_o), .m_rsp_rdata_o(ibus_rsp_rdata_o),
    .m_rsp_err_o  (ibus_rsp_err_o),
    .s_req_valid_o(i_valid), .s_req_ready_i(i_ready), .s_req_addr_o(i_addr),
    .s_req_we_o   (i_we),    .s_req_be_o   (i_be),    .s_req_wdata_o(i_wdata),
    .s_rsp_valid_i(i_rsp_valid), .s_rsp_rdata_i(i_rsp_rdata), .s_rsp_err_i(i_rsp_err)
  );

  htx_bus_demux #(
    .NumSlaves(4),
    .SlaveBase({TexBase, FbBase, IoBase, RamBase}),
    .SlaveMask({TexMask, FbMask, IoMask, RamMask}),
    .SlaveEnable({Gpu, Gpu, 1'b1, 1'b1})
  ) u_dbus_demux (
    .clk_i, .rst_ni,
    .m_req_valid_i(dbus_req_valid_i), .m_req_ready_o(dbus_req_ready_o),
    .m_req_addr_i (dbus_req_addr_i),  .m_req_we_i   (dbus_req_we_i),
    .m_req_be_i   (dbus_req_be_i),    .m_req_wdata_i(dbus_req_wdata_i),
    .m_rsp_valid_o(dbus_rsp_valid_o), .m_rsp_rdata_o(dbus_rsp_rdata_o),
    .m_rsp_err_o  (dbus_rsp_err_o),
    .s_req_valid_o(d_valid), .s_req_ready_i(d_ready), .s_req_addr_o(d_addr),
    .s_req_we_o   (d_we),    .s_req_be_o   (d_be),    .s_req_wdata_o(d_wdata),
    .s_rsp_valid_i(d_rsp_valid), .s_rsp_rdata_i(d_rsp_rdata), .s_rsp_err_i(d_rsp_err)
  );

  // ---- RAM, one port per CPU bus, each behind a stall injector ----
  logic        ra_valid, ra_ready, ra_we, ra_rsp_valid, ra_rsp_err;
  logic [31:0] ra_addr, ra_wdata, ra_rsp_rdata;
  logic [3:0]  ra_be;
  logic        rb_valid, rb_ready, rb_we, rb_rsp_valid, rb_rsp_err;
  logic [31:0] rb_addr, rb_wdata, rb_rsp_rdata;
  logic [3:0]  rb_be;

  htx_bus_stall #(.Present(StallInject), .Salt(32'h1234_5601)) u_stall_ram_a (
    .clk_i, .rst_ni, .en_i(stall_en_i), .seed_i(stall_seed_i),
    .m_req_valid_i(i_valid[0]), .m_req_ready_o(i_ready[0]), .m_req_addr_i(i_addr),
    .m_req_we_i(i_we), .m_req_be_i(i_be), .m_req_wdata_i(i_wdata),
    .m_rsp_valid_o(i_rsp_valid[0]), .m_rsp_rdata_o(i_rsp_rdata[31:0]), .m_rsp_err_o(i_rsp_err[0]),
    .s_req_valid_o(ra_valid), .s_req_ready_i(ra_ready), .s_req_addr_o(ra_addr),
    .s_req_we_o(ra_we), .s_req_be_o(ra_be), .s_req_wdata_o(ra_wdata),
    .s_rsp_valid_i(ra_rsp_valid), .s_rsp_rdata_i(ra_rsp_rdata), .s_rsp_err_i(ra_rsp_err)
  );

  htx_bus_stall #(.Present(StallInject), .Salt(32'h1234_5602)) u_stall_ram_b (
    .clk_i, .rst_ni, .en_i(stall_en_i), .seed_i(stall_seed_i),
    .m_req_valid_i(d_valid[0]), .m_req_ready_o(d_ready[0]), .m_req_addr_i(d_addr),
    .m_req_we_i(d_we), .m_req_be_i(d_be), .m_req_wdata_i(d_wdata),
    .m_rsp_valid_o(d_rsp_valid[0]), .m_rsp_rdata_o(d_rsp_rdata[31:0]), .m_rsp_err_o(d_rsp_err[0]),
    .s_req_valid_o(rb_valid), .s_req_ready_i(rb_ready), .s_req_addr_o(rb_addr),
    .s_req_we_o(rb_we), .s_req_be_o(rb_be), .s_req_wdata_o(rb_wdata),
    .s_rsp_valid_i(rb_rsp_valid), .s_rsp_rdata_i(rb_rsp_rdata), .s_rsp_err_i(rb_rsp_err)
  );

  htx_ram_dp #(.Bytes(RamBytes), .InitFile(RamInitFile)) u_ram (
    .clk_i, .rst_ni,
    .a_req_valid_i(ra_valid), .a_req_ready_o(ra_ready), .a_req_addr_i(ra_addr),
    .a_req_we_i(ra_we), .a_req_be_i(ra_be), .a_req_wdata_i(ra_wdata),
    .a_rsp_valid_o(ra_rsp_valid), .a_rsp_rdata_o(ra_rsp_rdata), .a_rsp_err_o(ra_rsp_err),
    .b_req_valid_i(rb_valid), .b_req_ready_o(rb_ready), .b_req_addr_i(rb_addr),
    .b_req_we_i(rb_we), .b_req_be_i(rb_be), .b_req_wdata_i(rb_wdata),
    .b_rsp_valid_o(rb_rsp_valid), .b_rsp_rdata_o(rb_rsp_rdata), .b_rsp_err_o(rb_rsp_err)
  );

  // ---- IO: the register-block demux, on the data port alone (dbus demux slave 1) ----
  logic [NumIo-1:0]    p_valid, p_ready, p_rsp_valid, p_rsp_err;
  logic [31:0]         p_addr, p_wdata;
  logic                p_we;
  logic [3:0]          p_be;
  logic [NumIo*32-1:0] p_rsp_rdata;

  htx_bus_demux #(
    .NumSlaves(NumIo),
    .SlaveBase({htx_video_reg_pkg::VIDEO_BASE_ADDR,
                htx_texture_reg_pkg::TEXTURE_BASE_ADDR, htx_raster_reg_pkg::RASTER_BASE_ADDR,
                htx_timer_reg_pkg::TIMER_BASE_ADDR, htx_uart_reg_pkg::UART_BASE_ADDR,
                htx_sysctrl_reg_pkg::SYSCTRL_BASE_ADDR}),
    .SlaveMask({RegMask, RegMask, RegMask, RegMask, RegMask, RegMask}),
    .SlaveEnable({Gpu, Gpu, Gpu, 1'b1, 1'b1, 1'b1})
  ) u_io_demux (
    .clk_i, .rst_ni,
    .m_req_valid_i(d_valid[1]), .m_req_ready_o(d_ready[1]), .m_req_addr_i(d_addr),
    .m_req_we_i(d_we), .m_req_be_i(d_be), .m_req_wdata_i(d_wdata),
    .m_rsp_valid_o(d_rsp_valid[1]), .m_rsp_rdata_o(d_rsp_rdata[63:32]), .m_rsp_err_o(d_rsp_err[1]),
    .s_req_valid_o(p_valid), .s_req_ready_i(p_ready), .s_req_addr_o(p_addr),
    .s_req_we_o(p_we), .s_req_be_o(p_be), .s_req_wdata_o(p_wdata),
    .s_rsp_valid_i(p_rsp_valid), .s_rsp_rdata_i(p_rsp_rdata), .s_rsp_err_i(p_rsp_err)
  );

  // RASTER and TEXTURE (demux slaves 3 and 4) join onto the GPU's register link 3 (see the
  // header); VIDEO (slave 5) is link 4.
  logic [NumLink-1:0]    l_valid, l_ready, l_rsp_valid, l_rsp_err;
  logic [NumLink*32-1:0] l_rsp_rdata;
  assign l_valid     = {p_valid[5], p_valid[3] | p_valid[4], p_valid[2:0]};
  assign p_ready     = {l_ready[4], l_ready[3], l_ready[3:0]};
  assign p_rsp_valid = {l_rsp_valid[4], l_rsp_valid[3], l_rsp_valid[3:0]};
  assign p_rsp_err   = {l_rsp_err[4], l_rsp_err[3], l_rsp_err[3:0]};
  assign p_rsp_rdata = {l_rsp_rdata[128 +: 32], l_rsp_rdata[96 +: 32], l_rsp_rdata[127:0]};

  // Peripheral-side links after the stall injectors.
  logic [NumLink-1:0]    q_valid, q_ready, q_we, q_rsp_valid, q_rsp_err;
  logic [NumLink*32-1:0] q_addr, q_wdata, q_rsp_rdata;
  logic [NumLink*4-1:0]  q_be;

  for (genvar k = 0; k < NumLink; k++) begin : g_io_stall
    htx_bus_stall #(.Present(StallInject), .Salt(32'h1234_5610 + 32'(k))) u_stall (
      .clk_i, .rst_ni, .en_i(stall_en_i), .seed_i(stall_seed_i),
      .m_req_valid_i(l_valid[k]), .m_req_ready_o(l_ready[k]), .m_req_addr_i(p_addr),
      .m_req_we_i(p_we), .m_req_be_i(p_be), .m_req_wdata_i(p_wdata),
      .m_rsp_valid_o(l_rsp_valid[k]), .m_rsp_rdata_o(l_rsp_rdata[k*32 +: 32]),
      .m_rsp_err_o(l_rsp_err[k]),
      .s_req_valid_o(q_valid[k]), .s_req_ready_i(q_ready[k]), .s_req_addr_o(q_addr[k*32 +: 32]),
      .s_req_we_o(q_we[k]), .s_req_be_o(q_be[k*4 +: 4]), .s_req_wdata_o(q_wdata[k*32 +: 32]),
      .s_rsp_valid_i(q_rsp_valid[k]), .s_rsp_rdata_i(q_rsp_rdata[k*32 +: 32]),
      .s_rsp_err_i(q_rsp_err[k])
    );
  end

  htx_sysctrl #(.ClockHz(ClockHz), .Sim(Sim)) u_sysctrl (
    .clk_i, .rst_ni,
    .req_valid_i(q_valid[0]), .req_ready_o(q_ready[0]), .req_addr_i(q_addr[0 +: 32]),
    .req_we_i(q_we[0]), .req_be_i(q_be[0 +: 4]), .req_wdata_i(q_wdata[0 +: 32]),
    .rsp_valid_o(q_rsp_valid[0]), .rsp_rdata_o(q_rsp_rdata[0 +: 32]), .rsp_err_o(q_rsp_err[0]),
    .sim_exit_o, .sim_exit_code_o, .sim_putchar_o, .sim_char_o
  );

  htx_uart u_uart (
    .clk_i, .rst_ni,
    .req_valid_i(q_valid[1]), .req_ready_o(q_ready[1]), .req_addr_i(q_addr[32 +: 32]),
    .req_we_i(q_we[1]), .req_be_i(q_be[4 +: 4]), .req_wdata_i(q_wdata[32 +: 32]),
    .rsp_valid_o(q_rsp_valid[1]), .rsp_rdata_o(q_rsp_rdata[32 +: 32]), .rsp_err_o(q_rsp_err[1]),
    .rx_i(uart_rx_i), .tx_o(uart_tx_o)
  );

  htx_timer u_timer (
    .clk_i, .rst_ni,
    .req_valid_i(q_valid[2]), .req_ready_o(q_ready[2]), .req_addr_i(q_addr[64 +: 32]),
    .req_we_i(q_we[2]), .req_be_i(q_be[8 +: 4]), .req_wdata_i(q_wdata[64 +: 32]),
    .rsp_valid_o(q_rsp_valid[2]), .rsp_rdata_o(q_rsp_rdata[64 +: 32]), .rsp_err_o(q_rsp_err[2]),
    .irq_o(timer_irq_o)
  );

  // The framebuffer/depth and texture windows join onto the GPU's memory link (see the header).
  logic        dg_valid, dg_ready, dg_rsp_valid, dg_rsp_err;
  logic [31:0] dg_rsp_rdata;
  assign dg_valid                = d_valid[2] | d_valid[3];
  assign d_ready[3:2]            = {2{dg_ready}};
  assign d_rsp_valid[3:2]        = {2{dg_rsp_valid}};
  assign d_rsp_err[3:2]          = {2{dg_rsp_err}};
  assign d_rsp_rdata[64 +: 64]   = {2{dg_rsp_rdata}};

  // ---- GPU: register port behind the IO demux, memory port on the data bus ----
  if (Gpu) begin : g_gpu
    logic        g_valid, g_ready, g_we, g_rsp_valid, g_rsp_err;
    logic [31:0] g_addr, g_wdata, g_rsp_rdata;
    logic [3:0]  g_be;

    htx_bus_stall #(.Present(StallInject), .Salt(32'h1234_5603)) u_stall_gpu_mem (
      .clk_i, .rst_ni, .en_i(stall_en_i), .seed_i(stall_seed_i),
      .m_req_valid_i(dg_valid), .m_req_ready_o(dg_ready), .m_req_addr_i(d_addr),
      .m_req_we_i(d_we), .m_req_be_i(d_be), .m_req_wdata_i(d_wdata),
      .m_rsp_valid_o(dg_rsp_valid), .m_rsp_rdata_o(dg_rsp_rdata), .m_rsp_err_o(dg_rsp_err),
      .s_req_valid_o(g_valid), .s_req_ready_i(g_ready), .s_req_addr_o(g_addr),
      .s_req_we_o(g_we), .s_req_be_o(g_be), .s_req_wdata_o(g_wdata),
      .s_rsp_valid_i(g_rsp_valid), .s_rsp_rdata_i(g_rsp_rdata), .s_rsp_err_i(g_rsp_err)
    );

    // Simulation speed (Sim only): the GPU is most of the SoC model, and Verilator evaluates its
    // logic on every clock it gets, so its clock runs only while it has work: a request on either of
    // its ports, the raster or the texture unit busy, or fewer than GateHold cycles after any of
    // these (responses, pipelines draining). The enable changes at the falling edge, so the gated
    // clock has no glitch. Every GPU flip-flop would hold its value on the cycles left out, so the
    // results are those of the free-running clock; the harness can run it free (`htx sim
    // --no-gpu-gate`) and the system tests compare the two (docs/soc.md, "Simulation speed").
    // Synthesis (Sim = 0) always gets clk_i.
    logic gpu_clk;
    logic        fbv_req, fbv_gnt, video_busy;
    logic [23:0] fbv_addr;
    logic [31:0] fbv_data;
    if (Sim) begin : g_sim_gpu_gate
      localparam int unsigned GateHold = 127;
      // Written by the harness: 1 = stop the GPU's clock while it is idle, 0 = let it run free.
      logic       gate_allow /* verilator public_flat_rw */;
      logic       active, en_q;
      logic [6:0] hold_q;
      assign active = q_valid[3] || g_valid || u_gpu.u_subsys.u_raster.busy ||
                      u_gpu.u_subsys.tex_busy || video_busy;
      always_ff @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) begin
          hold_q <= 7'(GateHold);
        end else if (active) begin
          hold_q <= 7'(GateHold);
        end else if (hold_q != 7'd0) begin
          hold_q <= hold_q - 7'd1;
        end
      end
      always_ff @(negedge clk_i or negedge rst_ni) begin
        if (!rst_ni) begin
          en_q <= 1'b1;
        end else begin
          en_q <= !gate_allow || active || (hold_q != 7'd0);
        end
      end
      assign gpu_clk = clk_i & en_q;
    end else begin : g_gpu_clk
      assign gpu_clk = clk_i;
      logic unused_video_busy;
      assign unused_video_busy = video_busy;
    end

    htx_gpu_icebreaker #(.FbPixels(FbPixels), .Methods(GpuMethods), .RasterCounters(GpuCounters),
                         .TexWindowRead(GpuTexRead), .FbSpram(GpuFbSpram),
                         .ColorPages(FbPages)) u_gpu (
      .clk_i(gpu_clk), .rst_ni,
      .reg_req_valid_i(q_valid[3]), .reg_req_ready_o(q_ready[3]), .reg_req_addr_i(q_addr[96 +: 32]),
      .reg_req_we_i(q_we[3]), .reg_req_be_i(q_be[12 +: 4]), .reg_req_wdata_i(q_wdata[96 +: 32]),
      .reg_rsp_valid_o(q_rsp_valid[3]), .reg_rsp_rdata_o(q_rsp_rdata[96 +: 32]),
      .reg_rsp_err_o(q_rsp_err[3]),
      .mem_req_valid_i(g_valid), .mem_req_ready_o(g_ready), .mem_req_addr_i(g_addr),
      .mem_req_we_i(g_we), .mem_req_be_i(g_be), .mem_req_wdata_i(g_wdata),
      .mem_rsp_valid_o(g_rsp_valid), .mem_rsp_rdata_o(g_rsp_rdata), .mem_rsp_err_o(g_rsp_err),
      .fbv_req_i(fbv_req), .fbv_addr_i(fbv_addr), .fbv_gnt_o(fbv_gnt), .fbv_data_o(fbv_data)
    );

    // VIDEO on the SoC's clock (the pixel clock), reading the GPU's colour memory; its reads keep
    // the simulation's GPU clock running (busy_o above).
    htx_video #(.SrcW(160), .SrcH(FbPixels / 160), .AddrW(24), .Pages(FbPages),
                .PageWords(FbPixels / 2)) u_video (
      .clk_i, .rst_ni,
      .req_valid_i(q_valid[4]), .req_ready_o(q_ready[4]), .req_addr_i(q_addr[128 +: 32]),
      .req_we_i(q_we[4]), .req_be_i(q_be[16 +: 4]), .req_wdata_i(q_wdata[128 +: 32]),
      .rsp_valid_o(q_rsp_valid[4]), .rsp_rdata_o(q_rsp_rdata[128 +: 32]), .rsp_err_o(q_rsp_err[4]),
      .fb_req_o(fbv_req), .fb_addr_o(fbv_addr), .fb_gnt_i(fbv_gnt), .fb_data_i(fbv_data),
      .de_o(video_de_o), .hsync_no(video_hsync_no), .vsync_no(video_vsync_no), .rgb_o(video_rgb_o),
      .busy_o(video_busy)
    );
  end else begin : g_no_gpu
    // The demuxes never select the GPU's links (SlaveEnable above): they only need defined outputs.
    assign q_ready[3]            = 1'b1;
    assign q_rsp_valid[3]        = 1'b0;
    assign q_rsp_err[3]          = 1'b0;
    assign q_rsp_rdata[96 +: 32] = '0;
    assign q_ready[4]             = 1'b1;
    assign q_rsp_valid[4]         = 1'b0;
    assign q_rsp_err[4]           = 1'b0;
    assign q_rsp_rdata[128 +: 32] = '0;
    assign video_de_o             = 1'b0;
    assign video_hsync_no         = 1'b1;
    assign video_vsync_no         = 1'b1;
    assign video_rgb_o            = '0;
    assign dg_ready              = 1'b1;
    assign dg_rsp_valid          = 1'b0;
    assign dg_rsp_err            = 1'b0;
    assign dg_rsp_rdata          = '0;
    logic unused_gpu_link;
    assign unused_gpu_link = ^{q_valid[4:3], q_addr[96 +: 64], q_we[4:3], q_be[12 +: 8],
                               q_wdata[96 +: 64], dg_valid};
  end
endmodule
