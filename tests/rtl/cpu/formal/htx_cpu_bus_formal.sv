// Formal harness (Yosys `sat`, bounded): htx_cpu on both buses against every slave behaviour the
// bus contract allows (docs/contracts.md, "On-chip bus"): any wait states on the request channel,
// a response at any time from a cycle after acceptance on, any read data and any error. The core
// starts from an arbitrary state (flip-flops without a reset are free) held in reset for the
// first cycle. Asserted: a request waiting for ready stays presented and unchanged; at most two
// instruction requests and one data request outstanding; instruction requests are aligned word
// reads; a data request's byte enables are those of an aligned access at its address.
// cov_* are reachability targets: the test also finds a trace to each, so that the assertions are
// not checked on a subset of behaviour that never issues a request.
module htx_cpu_bus_formal (
  input logic        clk_i,
  input logic        rst_ni,
  input logic        ibus_req_ready_i,
  input logic        ibus_rsp_valid_i,
  input logic [31:0] ibus_rsp_rdata_i,
  input logic        ibus_rsp_err_i,
  input logic        dbus_req_ready_i,
  input logic        dbus_rsp_valid_i,
  input logic [31:0] dbus_rsp_rdata_i,
  input logic        dbus_rsp_err_i
);
  logic        ibus_req_valid, ibus_req_we, dbus_req_valid, dbus_req_we;
  logic [31:0] ibus_req_addr, ibus_req_wdata, dbus_req_addr, dbus_req_wdata;
  logic [3:0]  ibus_req_be, dbus_req_be;

  htx_cpu u_cpu (
    .clk_i,
    .rst_ni,
    .ibus_req_valid_o (ibus_req_valid),
    .ibus_req_ready_i,
    .ibus_req_addr_o  (ibus_req_addr),
    .ibus_req_we_o    (ibus_req_we),
    .ibus_req_be_o    (ibus_req_be),
    .ibus_req_wdata_o (ibus_req_wdata),
    .ibus_rsp_valid_i,
    .ibus_rsp_rdata_i,
    .ibus_rsp_err_i,
    .dbus_req_valid_o (dbus_req_valid),
    .dbus_req_ready_i,
    .dbus_req_addr_o  (dbus_req_addr),
    .dbus_req_we_o    (dbus_req_we),
    .dbus_req_be_o    (dbus_req_be),
    .dbus_req_wdata_o (dbus_req_wdata),
    .dbus_rsp_valid_i,
    .dbus_rsp_rdata_i,
    .dbus_rsp_err_i
  );

  logic past_valid_q = 1'b0;
  always_ff @(posedge clk_i) begin
    past_valid_q <= 1'b1;
  end
  always_comb begin
    if (!past_valid_q) begin
      assume (!rst_ni);
    end
  end

  // Both slaves free within the contract; the core's requests checked to stay while they wait.
  logic [2:0] i_out, d_out;
  logic       i_waited_unused, d_waited;
  htx_bus_port_formal u_ibus (
    .clk_i,
    .rst_ni,
    .req_valid_i   (ibus_req_valid),
    .req_ready_i   (ibus_req_ready_i),
    .req_addr_i    (ibus_req_addr),
    .req_we_i      (ibus_req_we),
    .req_be_i      (ibus_req_be),
    .req_wdata_i   (ibus_req_wdata),
    .rsp_valid_i   (ibus_rsp_valid_i),
    .rsp_err_i     (ibus_rsp_err_i),
    .outstanding_o (i_out),
    .waited_o      (i_waited_unused)
  );
  htx_bus_port_formal u_dbus (
    .clk_i,
    .rst_ni,
    .req_valid_i   (dbus_req_valid),
    .req_ready_i   (dbus_req_ready_i),
    .req_addr_i    (dbus_req_addr),
    .req_we_i      (dbus_req_we),
    .req_be_i      (dbus_req_be),
    .req_wdata_i   (dbus_req_wdata),
    .rsp_valid_i   (dbus_rsp_valid_i),
    .rsp_err_i     (dbus_rsp_err_i),
    .outstanding_o (d_out),
    .waited_o      (d_waited)
  );

  always_comb begin
    if (rst_ni) begin
      assert (i_out <= 3'd2);
      assert (d_out <= 3'd1);
      if (ibus_req_valid) begin
        assert (!ibus_req_we && ibus_req_be == 4'b1111 && ibus_req_addr[1:0] == 2'b00);
      end
      if (dbus_req_valid) begin
        unique case (dbus_req_be)
          4'b1111, 4'b0011, 4'b0001: assert (dbus_req_addr[1:0] == 2'b00);
          4'b1100, 4'b0100:          assert (dbus_req_addr[1:0] == 2'b10);
          4'b0010:                   assert (dbus_req_addr[1:0] == 2'b01);
          4'b1000:                   assert (dbus_req_addr[1:0] == 2'b11);
          default:                   assert (1'b0);
        endcase
      end
    end
  end

  // Reachability targets.
  (* keep *) logic cov_dbus_waited_store, cov_dbus_waited_load;
  assign cov_dbus_waited_store = rst_ni && d_waited && dbus_req_ready_i && dbus_req_we;
  assign cov_dbus_waited_load  = rst_ni && d_waited && dbus_req_ready_i && !dbus_req_we;
endmodule
