// NumMasters bus masters sharing one slave link, round robin.
//
// Responses carry no master id, so the grant only moves to another master when nothing is
// outstanding; until then the owner may keep issuing pipelined requests. A request that has been
// presented to the slave but not yet accepted keeps its grant, so the slave sees stable request
// signals (contracts.md).
module htx_bus_arbiter #(
  parameter int unsigned NumMasters = 2,
  parameter int unsigned CntWidth   = 2
) (
  input  logic                       clk_i,
  input  logic                       rst_ni,

  input  logic [NumMasters-1:0]      m_req_valid_i,
  output logic [NumMasters-1:0]      m_req_ready_o,
  input  logic [NumMasters*32-1:0]   m_req_addr_i,
  input  logic [NumMasters-1:0]      m_req_we_i,
  input  logic [NumMasters*4-1:0]    m_req_be_i,
  input  logic [NumMasters*32-1:0]   m_req_wdata_i,
  output logic [NumMasters-1:0]      m_rsp_valid_o,
  output logic [31:0]                m_rsp_rdata_o,
  output logic                       m_rsp_err_o,

  output logic                       s_req_valid_o,
  input  logic                       s_req_ready_i,
  output logic [31:0]                s_req_addr_o,
  output logic                       s_req_we_o,
  output logic [3:0]                 s_req_be_o,
  output logic [31:0]                s_req_wdata_o,
  input  logic                       s_rsp_valid_i,
  input  logic [31:0]                s_rsp_rdata_i,
  input  logic                       s_rsp_err_i
);
  localparam int unsigned IdxWidth = (NumMasters > 1) ? $clog2(NumMasters) : 1;
  localparam logic [CntWidth-1:0] CntMax = {CntWidth{1'b1}};

  logic [IdxWidth-1:0] owner_d, owner_q;  // master that holds the grant / whose responses are due
  logic [IdxWidth-1:0] grant;
  logic                locked;            // grant may not move this cycle
  logic                hold_q;            // a request was presented last cycle and not accepted
  logic [CntWidth-1:0] cnt_d, cnt_q;
  logic                accept;

  assign locked = hold_q || (cnt_q != '0);

  // Round robin: search from the master after the last owner.
  always_comb begin
    grant = owner_q;
    if (!locked) begin
      // Walk backwards from the master furthest after the owner, so the nearest valid one wins.
      for (int k = NumMasters; k >= 1; k--) begin
        if (m_req_valid_i[(32'(owner_q) + 32'(k)) % NumMasters]) begin
          grant = IdxWidth'((32'(owner_q) + 32'(k)) % NumMasters);
        end
      end
    end
  end

  assign s_req_valid_o = m_req_valid_i[grant] && (cnt_q != CntMax);
  assign s_req_addr_o  = m_req_addr_i[32'(grant)*32 +: 32];
  assign s_req_we_o    = m_req_we_i[grant];
  assign s_req_be_o    = m_req_be_i[32'(grant)*4 +: 4];
  assign s_req_wdata_o = m_req_wdata_i[32'(grant)*32 +: 32];
  assign accept        = s_req_valid_o && s_req_ready_i;

  always_comb begin
    m_req_ready_o        = '0;
    m_req_ready_o[grant] = s_req_ready_i && (cnt_q != CntMax);
    m_rsp_valid_o        = '0;
    m_rsp_valid_o[owner_q] = s_rsp_valid_i;
  end
  assign m_rsp_rdata_o = s_rsp_rdata_i;
  assign m_rsp_err_o   = s_rsp_err_i;

  always_comb begin
    cnt_d = cnt_q;
    if (accept && !s_rsp_valid_i) begin
      cnt_d = cnt_q + 1'b1;
    end else if (!accept && s_rsp_valid_i) begin
      cnt_d = cnt_q - 1'b1;
    end
    owner_d = s_req_valid_o ? grant : owner_q;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      cnt_q   <= '0;
      owner_q <= '0;
      hold_q  <= 1'b0;
    end else begin
      cnt_q   <= cnt_d;
      owner_q <= owner_d;
      hold_q  <= s_req_valid_o && !s_req_ready_i;
    end
  end
endmodule
