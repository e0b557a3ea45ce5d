// Random wait-state injector for one slave link (simulation aid; htx sim --stall-seed).
//
// With en_i low it is a wire. With en_i high, a pseudo-random sequence (xorshift32, seeded from
// seed_i ^ Salt in the first cycle after reset) withholds requests from the slave and delays
// responses, so every master is exercised against arbitrary wait states on both channels. Delayed
// responses wait in a small FIFO; requests are held back while it could overflow. A request shown to
// the slave stays shown until accepted, as the protocol requires. en_i must not change after reset.
// With Present = 0 (board builds) the module is only wires.
module htx_bus_stall #(
  parameter bit          Present = 1'b1,   // 0: no logic at all, en_i and seed_i are ignored
  parameter logic [31:0] Salt = 32'h9E37_79B9,
  parameter int unsigned Depth = 4   // power of two
) (
  input  logic        clk_i,
  input  logic        rst_ni,
  input  logic        en_i,
  input  logic [31:0] seed_i,

  input  logic        m_req_valid_i,
  output logic        m_req_ready_o,
  input  logic [31:0] m_req_addr_i,
  input  logic        m_req_we_i,
  input  logic [3:0]  m_req_be_i,
  input  logic [31:0] m_req_wdata_i,
  output logic        m_rsp_valid_o,
  output logic [31:0] m_rsp_rdata_o,
  output logic        m_rsp_err_o,

  output logic        s_req_valid_o,
  input  logic        s_req_ready_i,
  output logic [31:0] s_req_addr_o,
  output logic        s_req_we_o,
  output logic [3:0]  s_req_be_o,
  output logic [31:0] s_req_wdata_o,
  input  logic        s_rsp_valid_i,
  input  logic [31:0] s_rsp_rdata_i,
  input  logic        s_rsp_err_i
);
  if (!Present) begin : g_wire
    logic unused;
    assign unused        = clk_i ^ rst_ni ^ en_i ^ (^seed_i);
    assign s_req_valid_o = m_req_valid_i;
    assign m_req_ready_o = s_req_ready_i;
    assign s_req_addr_o  = m_req_addr_i;
    assign s_req_we_o    = m_req_we_i;
    assign s_req_be_o    = m_req_be_i;
    assign s_req_wdata_o = m_req_wdata_i;
    assign m_rsp_valid_o = s_rsp_valid_i;
    assign m_rsp_rdata_o = s_rsp_rdata_i;
    assign m_rsp_err_o   = s_rsp_err_i;
  end else begin : g_stall
    localparam int unsigned PtrWidth = $clog2(Depth);

    logic [31:0] rng_q, rng_d;
    logic        hold_q;             // request shown to the slave last cycle and not yet accepted
    logic        req_go, rsp_go;
    logic [PtrWidth:0] pending_q;    // accepted by the slave, response not yet given to the master
    logic [PtrWidth:0] fifo_cnt_q;
    logic [PtrWidth-1:0] wptr_q, rptr_q;
    logic [31:0] fifo_rdata_q [Depth];
    logic        fifo_err_q [Depth];
    logic        push, pop, s_accept;

    // xorshift32: never reaches 0 from a non-zero seed.
    always_comb begin
      rng_d = rng_q;
      rng_d = rng_d ^ (rng_d << 13);
      rng_d = rng_d ^ (rng_d >> 17);
      rng_d = rng_d ^ (rng_d << 5);
    end

    assign req_go = hold_q || rng_q[3];
    assign rsp_go = rng_q[11] || rng_q[19];  // responses released three times in four

    assign s_req_addr_o  = m_req_addr_i;
    assign s_req_we_o    = m_req_we_i;
    assign s_req_be_o    = m_req_be_i;
    assign s_req_wdata_o = m_req_wdata_i;

    always_comb begin
      if (!en_i) begin
        s_req_valid_o = m_req_valid_i;
        m_req_ready_o = s_req_ready_i;
        m_rsp_valid_o = s_rsp_valid_i;
        m_rsp_rdata_o = s_rsp_rdata_i;
        m_rsp_err_o   = s_rsp_err_i;
      end else begin
        s_req_valid_o = m_req_valid_i && req_go && (pending_q != (PtrWidth+1)'(Depth));
        m_req_ready_o = s_req_ready_i && req_go && (pending_q != (PtrWidth+1)'(Depth));
        m_rsp_valid_o = (fifo_cnt_q != '0) && rsp_go;
        m_rsp_rdata_o = m_rsp_valid_o ? fifo_rdata_q[rptr_q] : '0;
        m_rsp_err_o   = m_rsp_valid_o && fifo_err_q[rptr_q];
      end
    end

    assign s_accept = s_req_valid_o && s_req_ready_i;
    assign push     = en_i && s_rsp_valid_i;
    assign pop      = en_i && m_rsp_valid_o;

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        rng_q      <= '0;
        hold_q     <= 1'b0;
        pending_q  <= '0;
        fifo_cnt_q <= '0;
        wptr_q     <= '0;
        rptr_q     <= '0;
      end else begin
        // Zero means "not seeded yet": xorshift32 never returns to zero from a non-zero state.
        if (rng_q == '0) begin
          rng_q <= ((seed_i ^ Salt) == '0) ? Salt : (seed_i ^ Salt);
        end else begin
          rng_q <= rng_d;
        end
        hold_q    <= s_req_valid_o && !s_req_ready_i;
        if (en_i) begin
          pending_q  <= pending_q + (PtrWidth+1)'(s_accept) - (PtrWidth+1)'(pop);
          fifo_cnt_q <= fifo_cnt_q + (PtrWidth+1)'(push) - (PtrWidth+1)'(pop);
          if (push) wptr_q <= wptr_q + 1'b1;
          if (pop)  rptr_q <= rptr_q + 1'b1;
        end
      end
    end

    always_ff @(posedge clk_i) begin
      if (push) begin
        fifo_rdata_q[wptr_q] <= s_rsp_rdata_i;
        fifo_err_q[wptr_q]   <= s_rsp_err_i;
      end
    end

  end
endmodule
