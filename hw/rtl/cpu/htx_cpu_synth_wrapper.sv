// Place-and-route harness for measuring htx_cpu alone on a small FPGA package: every bus input of
// the core comes from a register chain fed by one pin and every output is folded into one
// registered pin, so the core's logic stays alive and all its paths are timed register to register.
// Not part of any SoC.
module htx_cpu_synth_wrapper (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic din_i,
  output logic dout_o
);

  localparam int unsigned InBits = 1 + 1 + 32 + 1 + 1 + 1 + 32 + 1;

  logic [InBits-1:0] in_q;
  always_ff @(posedge clk_i) begin
    in_q <= {in_q[InBits-2:0], din_i};
  end

  logic        ibus_req_valid, ibus_req_we, dbus_req_valid, dbus_req_we;
  logic [31:0] ibus_req_addr, ibus_req_wdata, dbus_req_addr, dbus_req_wdata;
  logic [3:0]  ibus_req_be, dbus_req_be;

  // The window for the UP5K's 128 KiB of SPRAM, as the SoC sets it (twice the RAM).
  htx_cpu #(.PcBits(18)) u_cpu (
    .clk_i,
    .rst_ni,
    .ibus_req_valid_o (ibus_req_valid),
    .ibus_req_ready_i (in_q[0]),
    .ibus_req_addr_o  (ibus_req_addr),
    .ibus_req_we_o    (ibus_req_we),
    .ibus_req_be_o    (ibus_req_be),
    .ibus_req_wdata_o (ibus_req_wdata),
    .ibus_rsp_valid_i (in_q[1]),
    .ibus_rsp_rdata_i (in_q[33:2]),
    .ibus_rsp_err_i   (in_q[34]),
    .dbus_req_valid_o (dbus_req_valid),
    .dbus_req_ready_i (in_q[35]),
    .dbus_req_addr_o  (dbus_req_addr),
    .dbus_req_we_o    (dbus_req_we),
    .dbus_req_be_o    (dbus_req_be),
    .dbus_req_wdata_o (dbus_req_wdata),
    .dbus_rsp_valid_i (in_q[36]),
    .dbus_rsp_rdata_i (in_q[68:37]),
    .dbus_rsp_err_i   (in_q[69])
  );

  // Register every output first so that the core's output paths end at a flip-flop.
  logic [139:0] out_q;
  always_ff @(posedge clk_i) begin
    out_q  <= {ibus_req_valid, ibus_req_we, ibus_req_be, ibus_req_addr, ibus_req_wdata,
               dbus_req_valid, dbus_req_we, dbus_req_be, dbus_req_addr, dbus_req_wdata};
    dout_o <= ^out_q;
  end

endmodule
