// Formal harness part (Yosys `sat`): one bus link whose slave is free within the bus contract
// (docs/contracts.md, "On-chip bus"), and the master's side of the contract checked.
// Assumed of the slave: a response only for an accepted request without one yet, never in the
// cycle of its acceptance nor in reset; an error only with a response. Any ready, data and timing
// otherwise. Asserted of the master: a request that waited for ready is presented again, with its
// address, write flag, byte enables and data unchanged.
module htx_bus_port_formal (
  input  logic        clk_i,
  input  logic        rst_ni,
  input  logic        req_valid_i,
  input  logic        req_ready_i,
  input  logic [31:0] req_addr_i,
  input  logic        req_we_i,
  input  logic [3:0]  req_be_i,
  input  logic [31:0] req_wdata_i,
  input  logic        rsp_valid_i,
  input  logic        rsp_err_i,
  output logic [2:0]  outstanding_o,  // accepted requests without a response
  output logic        waited_o        // the request of the last cycle waited for ready
);
  logic [2:0] out_q = 3'd0;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      out_q <= 3'd0;
    end else begin
      out_q <= out_q + 3'(req_valid_i && req_ready_i) - 3'(rsp_valid_i);
    end
  end
  assign outstanding_o = out_q;

  logic        waited_q = 1'b0;
  logic [31:0] addr_q, wdata_q;
  logic        we_q;
  logic [3:0]  be_q;
  always_ff @(posedge clk_i) begin
    waited_q <= rst_ni && req_valid_i && !req_ready_i;
    addr_q   <= req_addr_i;
    we_q     <= req_we_i;
    be_q     <= req_be_i;
    wdata_q  <= req_wdata_i;
  end
  assign waited_o = waited_q;

  always_comb begin
    if (out_q == 3'd0 || !rst_ni) begin
      assume (!rsp_valid_i);
    end
    if (!rsp_valid_i) begin
      assume (!rsp_err_i);
    end
    if (rst_ni && waited_q) begin
      assert (req_valid_i && req_addr_i == addr_q && req_we_i == we_q && req_be_i == be_q &&
              req_wdata_i == wdata_q);
    end
  end
endmodule
