// Simulation top of the SoC (Verilated): 128 KiB RAM, simulation-only SYSCTRL ports, random wait states
// available on every slave, and the CPU's counters brought out for the harness's report.
// Simulation only (hierarchical references); boards instantiate htx_soc directly.
module htx_soc_sim_top #(
  parameter int unsigned RamBytes = 131072,
  parameter int unsigned ClockHz  = 12_000_000
) (
  input  logic        clk_i,
  input  logic        rst_ni,

  input  logic        uart_rx_i,
  output logic        uart_tx_o,

  output logic        sim_exit_o,
  output logic [7:0]  sim_exit_code_o,
  output logic        sim_putchar_o,
  output logic [7:0]  sim_char_o,

  output logic        video_de_o,      // the scan-out (htx_video), for a harness that watches it
  output logic        video_hsync_no,
  output logic        video_vsync_no,
  output logic [23:0] video_rgb_o,

  output logic [63:0] instret_o,
  // The instruction in the CPU's execute stage (`htx sim --hotspots` charges each clock to it).
  output logic        cpu_e_valid_o,  // execute holds an instruction that is not squashed
  output logic [31:0] cpu_e_pc_o,     // its address
  output logic        cpu_e_done_o    // it completes this clock
);
  logic timer_irq_unused;

  // Random wait states: set once by the harness before reset, and taken into flip-flops while reset
  // is held. Not ports, and not used directly: the Verilated model re-evaluates, on every eval(), all
  // logic that depends combinationally on a top-level input or on a variable the harness may write,
  // and through the stall units that is the whole bus fabric and the CPU's hand-shakes.
  logic        stall_en   /* verilator public_flat_rw */;
  logic [31:0] stall_seed /* verilator public_flat_rw */;
  logic        stall_en_q;
  logic [31:0] stall_seed_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      stall_en_q   <= stall_en;
      stall_seed_q <= stall_seed;
    end
  end

  htx_soc #(
    .RamBytes(RamBytes), .ClockHz(ClockHz), .Sim(1'b1), .StallInject(1'b1)
  ) u_soc (
    .clk_i, .rst_ni,
    .uart_rx_i, .uart_tx_o,
    .timer_irq_o(timer_irq_unused),
    .sim_exit_o, .sim_exit_code_o, .sim_putchar_o, .sim_char_o,
    .video_de_o, .video_hsync_no, .video_vsync_no, .video_rgb_o,
    .stall_en_i(stall_en_q), .stall_seed_i(stall_seed_q)
  );

  assign instret_o     = u_soc.u_cpu.u_csr.instret_q;
  assign cpu_e_valid_o = u_soc.u_cpu.e_live;  // not a squashed one
  assign cpu_e_pc_o    = {u_soc.u_cpu.e_pc_q, 2'b00};
  assign cpu_e_done_o  = u_soc.u_cpu.e_done;

  // Where the CPU's clocks go (`htx sim --profile`); the harness reads the counts.
  htx_cpu_profile u_cpu_profile (
    .clk_i, .rst_ni,
    .e_valid_i    (u_soc.u_cpu.e_valid_q),
    .e_done_i     (u_soc.u_cpu.e_done),
    .e_accept_i   (u_soc.u_cpu.e_accept),
    .e_load_i     (u_soc.u_cpu.e_q.load),
    .e_block_i    (u_soc.u_cpu.e_block),
    .unit_wait_i  (u_soc.u_cpu.unit_wait_q),
    .w_ready_i    (u_soc.u_cpu.w_ready),
    .w_trap_i     (u_soc.u_cpu.w_trap),
    .redirect_i   (u_soc.u_cpu.redirect_q),
    .d_valid_i    (u_soc.u_cpu.d_valid_q),
    .d_go_i       (u_soc.u_cpu.d_go),
    .d_hazard_i   (u_soc.u_cpu.d_hazard),
    .d_free_i     (u_soc.u_cpu.d_free),
    .d_jump_i     (u_soc.u_cpu.d_redirect),
    .f_take_i     (u_soc.u_cpu.f_take),
    .f_valid_i    (u_soc.u_cpu.f_valid)
  );
endmodule
