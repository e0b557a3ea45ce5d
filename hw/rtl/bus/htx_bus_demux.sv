// One bus master to NumSlaves slaves, decoded by address. An address that no slave claims goes to an
// internal error responder, which accepts it and answers one cycle later with rsp_err = 1 (rdata 0),
// so a stray access never hangs the bus.
//
// Responses must come back in request order (contracts.md). Slaves have different latencies, so the
// demux only lets requests go to one target at a time: a request for a different target waits until
// every outstanding response of the current one has returned. Back-to-back accesses to the same slave
// stay fully pipelined. Request address, write data and byte enables are broadcast to every slave;
// only the valid is steered.
module htx_bus_demux #(
  parameter int unsigned NumSlaves = 2,
  // Slave i claims addresses with (addr & SlaveMask[i]) == SlaveBase[i]; the lowest i wins.
  parameter logic [NumSlaves*32-1:0] SlaveBase = '0,
  parameter logic [NumSlaves*32-1:0] SlaveMask = '0,
  // Slave i claims nothing while SlaveEnable[i] is 0 (a slave a build leaves out): its addresses go
  // to the error responder like every unclaimed address.
  parameter logic [NumSlaves-1:0]    SlaveEnable = '1,
  // Responses that may be outstanding at once (at most 2**CntWidth - 1).
  parameter int unsigned CntWidth = 2
) (
  input  logic                      clk_i,
  input  logic                      rst_ni,

  input  logic                      m_req_valid_i,
  output logic                      m_req_ready_o,
  input  logic [31:0]               m_req_addr_i,
  input  logic                      m_req_we_i,
  input  logic [3:0]                m_req_be_i,
  input  logic [31:0]               m_req_wdata_i,
  output logic                      m_rsp_valid_o,
  output logic [31:0]               m_rsp_rdata_o,
  output logic                      m_rsp_err_o,

  output logic [NumSlaves-1:0]      s_req_valid_o,
  input  logic [NumSlaves-1:0]      s_req_ready_i,
  output logic [31:0]               s_req_addr_o,
  output logic                      s_req_we_o,
  output logic [3:0]                s_req_be_o,
  output logic [31:0]               s_req_wdata_o,
  input  logic [NumSlaves-1:0]      s_rsp_valid_i,
  input  logic [NumSlaves*32-1:0]   s_rsp_rdata_i,
  input  logic [NumSlaves-1:0]      s_rsp_err_i
);
  // Target index NumSlaves is the error responder.
  localparam int unsigned SelWidth = $clog2(NumSlaves + 1);
  localparam logic [SelWidth-1:0] ErrSel = SelWidth'(NumSlaves);
  localparam logic [CntWidth-1:0] CntMax = {CntWidth{1'b1}};

  logic [SelWidth-1:0] target;
  logic [SelWidth-1:0] sel_d, sel_q;
  logic [CntWidth-1:0] cnt_d, cnt_q;
  logic                allowed, accept, rsp_valid;
  logic                target_ready;
  logic                err_rsp_q;

  always_comb begin
    target = ErrSel;
    for (int i = NumSlaves - 1; i >= 0; i--) begin
      if (SlaveEnable[i] && (m_req_addr_i & SlaveMask[i*32 +: 32]) == SlaveBase[i*32 +: 32]) begin
        target = SelWidth'(i);
      end
    end
  end

  assign allowed = ((cnt_q == '0) || (sel_q == target)) && (cnt_q != CntMax);

  always_comb begin
    s_req_valid_o = '0;
    target_ready  = 1'b1;  // the error responder is always ready
    for (int i = 0; i < NumSlaves; i++) begin
      if (target == SelWidth'(i)) begin
        s_req_valid_o[i] = m_req_valid_i && allowed;
        target_ready     = s_req_ready_i[i];
      end
    end
  end

  assign m_req_ready_o = allowed && target_ready;
  assign accept        = m_req_valid_i && m_req_ready_o;

  assign s_req_addr_o  = m_req_addr_i;
  assign s_req_we_o    = m_req_we_i;
  assign s_req_be_o    = m_req_be_i;
  assign s_req_wdata_o = m_req_wdata_i;

  // Response from the current target (only that one can have responses outstanding).
  always_comb begin
    rsp_valid     = err_rsp_q;
    m_rsp_rdata_o = '0;
    m_rsp_err_o   = err_rsp_q;
    for (int i = 0; i < NumSlaves; i++) begin
      if (sel_q == SelWidth'(i)) begin
        rsp_valid     = s_rsp_valid_i[i];
        m_rsp_rdata_o = s_rsp_rdata_i[i*32 +: 32];
        m_rsp_err_o   = s_rsp_err_i[i];
      end
    end
  end
  assign m_rsp_valid_o = rsp_valid;

  always_comb begin
    cnt_d = cnt_q;
    if (accept && !rsp_valid) begin
      cnt_d = cnt_q + 1'b1;
    end else if (!accept && rsp_valid) begin
      cnt_d = cnt_q - 1'b1;
    end
    sel_d = accept ? target : sel_q;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      cnt_q     <= '0;
      sel_q     <= '0;
      err_rsp_q <= 1'b0;
    end else begin
      cnt_q     <= cnt_d;
      sel_q     <= sel_d;
      err_rsp_q <= accept && (target == ErrSel);
    end
  end
endmodule
