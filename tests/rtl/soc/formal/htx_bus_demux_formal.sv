// Formal harness (Yosys `sat`): htx_bus_demux between a master and three slaves, each free within
// the bus contract (docs/contracts.md, "On-chip bus"). Slave 0 claims one 4 KiB page, slave 1 a
// quarter of the address space that overlaps it (slave 0 must win), slave 2 is built out
// (SlaveEnable 0: its addresses get error responses like every unclaimed one).
// A scoreboard of the master's outstanding requests (which target each went to, oldest first)
// checks that every request reaches the one slave that claims its address and nothing else, that
// the master gets exactly one response per request, in request order, carrying the data and error
// of the slave that took it, that an unclaimed address is answered with an error in the next cycle
// and is never refused while nothing is outstanding, and that a request waiting for a slave's
// ready stays presented and unchanged on the slave side.
module htx_bus_demux_formal (
  input logic        clk_i,
  input logic        rst_ni,
  input logic        m_req_valid_i,
  input logic [31:0] m_req_addr_i,
  input logic        m_req_we_i,
  input logic [3:0]  m_req_be_i,
  input logic [31:0] m_req_wdata_i,
  input logic [2:0]  s_req_ready_i,
  input logic [2:0]  s_rsp_valid_i,
  input logic [95:0] s_rsp_rdata_i,
  input logic [2:0]  s_rsp_err_i
);
  localparam int unsigned NumSlaves = 3;
  localparam logic [95:0] Base = {32'h3000_0000, 32'h0000_0000, 32'h2000_0000};
  localparam logic [95:0] Mask = {32'hF000_0000, 32'hC000_0000, 32'hFFFF_F000};
  localparam logic [2:0]  Enable = 3'b011;
  localparam logic [1:0]  ErrTarget = 2'd3;

  logic        m_req_ready, m_rsp_valid, m_rsp_err;
  logic [31:0] m_rsp_rdata, s_req_addr, s_req_wdata;
  logic [2:0]  s_req_valid;
  logic        s_req_we;
  logic [3:0]  s_req_be;

  htx_bus_demux #(
    .NumSlaves   (NumSlaves),
    .SlaveBase   (Base),
    .SlaveMask   (Mask),
    .SlaveEnable (Enable),
    .CntWidth    (2)
  ) u_demux (
    .clk_i,
    .rst_ni,
    .m_req_valid_i,
    .m_req_ready_o (m_req_ready),
    .m_req_addr_i,
    .m_req_we_i,
    .m_req_be_i,
    .m_req_wdata_i,
    .m_rsp_valid_o (m_rsp_valid),
    .m_rsp_rdata_o (m_rsp_rdata),
    .m_rsp_err_o   (m_rsp_err),
    .s_req_valid_o (s_req_valid),
    .s_req_ready_i,
    .s_req_addr_o  (s_req_addr),
    .s_req_we_o    (s_req_we),
    .s_req_be_o    (s_req_be),
    .s_req_wdata_o (s_req_wdata),
    .s_rsp_valid_i,
    .s_rsp_rdata_i,
    .s_rsp_err_i
  );

  logic past_valid_q = 1'b0;
  always_ff @(posedge clk_i) begin
    past_valid_q <= 1'b1;
  end

  // The target that claims the master's address, computed here independently of the demux.
  logic [1:0] claim;
  always_comb begin
    if (Enable[0] && (m_req_addr_i & Mask[31:0]) == Base[31:0]) begin
      claim = 2'd0;
    end else if (Enable[1] && (m_req_addr_i & Mask[63:32]) == Base[63:32]) begin
      claim = 2'd1;
    end else if (Enable[2] && (m_req_addr_i & Mask[95:64]) == Base[95:64]) begin
      claim = 2'd2;
    end else begin
      claim = ErrTarget;
    end
  end

  logic m_accept;
  assign m_accept = m_req_valid_i && m_req_ready;

  // Scoreboard: the targets of the master's outstanding requests, oldest in sb_q[0].
  logic [1:0] sb_q [4];
  logic [2:0] sb_n_q = 3'd0;

  logic [1:0] head;
  assign head = sb_q[0];

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      sb_n_q <= 3'd0;
    end else begin
      if (m_rsp_valid) begin
        sb_q[0] <= sb_q[1];
        sb_q[1] <= sb_q[2];
        sb_q[2] <= sb_q[3];
      end
      if (m_accept) begin
        sb_q[3'(sb_n_q) - 3'(m_rsp_valid)] <= claim;
      end
      sb_n_q <= sb_n_q + 3'(m_accept) - 3'(m_rsp_valid);
    end
  end

  // Each slave free within the contract; a request waiting for it checked to stay unchanged.
  for (genvar i = 0; i < 3; i++) begin : g_slave
    logic [2:0] out_unused;
    logic       waited_unused;
    htx_bus_port_formal u_port (
      .clk_i,
      .rst_ni,
      .req_valid_i   (s_req_valid[i]),
      .req_ready_i   (s_req_ready_i[i]),
      .req_addr_i    (s_req_addr),
      .req_we_i      (s_req_we),
      .req_be_i      (s_req_be),
      .req_wdata_i   (s_req_wdata),
      .rsp_valid_i   (s_rsp_valid_i[i]),
      .rsp_err_i     (s_rsp_err_i[i]),
      .outstanding_o (out_unused),
      .waited_o      (waited_unused)
    );
  end

  // The master holds a request that waits.
  logic        m_waited_q = 1'b0;
  logic [31:0] m_addr_q, m_wdata_q;
  logic        m_we_q;
  logic [3:0]  m_be_q;
  always_ff @(posedge clk_i) begin
    m_waited_q <= rst_ni && m_req_valid_i && !m_req_ready;
    m_addr_q   <= m_req_addr_i;
    m_we_q     <= m_req_we_i;
    m_be_q     <= m_req_be_i;
    m_wdata_q  <= m_req_wdata_i;
  end
  always_comb begin
    if (!past_valid_q) begin
      assume (!rst_ni);
    end
    if (m_waited_q) begin
      assume (m_req_valid_i && m_req_addr_i == m_addr_q && m_req_we_i == m_we_q &&
              m_req_be_i == m_be_q && m_req_wdata_i == m_wdata_q);
    end
  end

  logic err_accept_q = 1'b0;
  always_ff @(posedge clk_i) begin
    err_accept_q <= rst_ni && m_accept && claim == ErrTarget;
  end

  always_comb begin
    if (rst_ni) begin
      // Requests reach the claiming slave only, and the master's hand-shake is that slave's.
      assert (s_req_addr == m_req_addr_i && s_req_we == m_req_we_i && s_req_be == m_req_be_i &&
              s_req_wdata == m_req_wdata_i);
      for (int i = 0; i < 3; i++) begin
        if (s_req_valid[i]) begin
          assert (m_req_valid_i && claim == 2'(i));
        end
        if (m_accept && claim == 2'(i)) begin
          assert (s_req_valid[i] && s_req_ready_i[i]);
        end
        if (s_req_valid[i] && s_req_ready_i[i]) begin
          assert (m_accept);
        end
      end
      // One response per request, in order, from the target that took it.
      if (m_rsp_valid) begin
        assert (sb_n_q != 3'd0);
        if (head == ErrTarget) begin
          assert (m_rsp_err && m_rsp_rdata == 32'h0);
        end else begin
          assert (s_rsp_valid_i[head] && m_rsp_err == s_rsp_err_i[head] &&
                  m_rsp_rdata == s_rsp_rdata_i[32*head +: 32]);
        end
      end
      for (int i = 0; i < 3; i++) begin
        if (s_rsp_valid_i[i]) begin
          assert (m_rsp_valid && sb_n_q != 3'd0 && head == 2'(i));
        end
      end
      // An unclaimed address: never refused while nothing is outstanding, answered a cycle later.
      if (m_req_valid_i && claim == ErrTarget && sb_n_q == 3'd0) begin
        assert (m_req_ready);
      end
      if (err_accept_q) begin
        assert (m_rsp_valid && m_rsp_err);
      end
      assert (sb_n_q <= 3'd3);
    end
  end

  (* keep *) logic cov_overlap_rsp_three_out;
  assign cov_overlap_rsp_three_out = rst_ni && m_rsp_valid && head == 2'd1 && sb_n_q == 3'd3;
endmodule
