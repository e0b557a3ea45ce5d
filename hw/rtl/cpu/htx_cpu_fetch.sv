// Instruction fetch: issues sequential word requests on the instruction bus and hands the
// instructions, in order with their PCs, to decode.
//
// At most two instructions are in flight or buffered, so every response has a place to go (the bus
// cannot back-pressure responses) while a one-cycle memory still streams one word per clock: a
// request goes out whenever fewer than two are outstanding or buffered, counting registered state
// only, which also guarantees a presented request is never withdrawn. Decode reads the buffer head,
// or the arriving response directly when the buffer is empty.
//
// Two kinds of redirect flush the buffer and mark every request still in flight as stale (stale
// responses are dropped as they arrive): redirect_i (execute's or write-back's) and predict_i
// (decode's branch prediction). Both addresses come from registers, so either goes on the bus in
// the same cycle. If a redirect comes while a request waits for ready, that request stays on the
// bus (the protocol forbids withdrawing it) and the new address follows it.
//
// Instructions execute from the window [0, 2^PcBits - 4] only (docs/cpu.md, "Executable window"),
// so the request and head PCs hold bits PcBits-1:2. Outside it, fetch hands decode instruction
// access faults instead of instructions, each as a faulting fetch (AUIPC x0, 0 with instr_err_o)
// at the full address: after a redirect_i whose target is outside (redirect_out_i; its bits 31:PcBits
// in redirect_hi_i), and at the window's last word, which a sequential fetch reaches by running off
// the window's end. Requests stop after an outside redirect and responses are dropped; at the last
// word the requests and responses that follow it belong to instructions behind a fault, which the
// fault's trap squashes.
module htx_cpu_fetch #(
  parameter logic [31:0] BootAddr = 32'h0000_0000,
  parameter int unsigned PcBits   = 18
) (
  input  logic        clk_i,
  input  logic        rst_ni,

  output logic        ibus_req_valid_o,
  input  logic        ibus_req_ready_i,
  output logic [31:0] ibus_req_addr_o,
  input  logic        ibus_rsp_valid_i,
  input  logic [31:0] ibus_rsp_rdata_i,
  input  logic        ibus_rsp_err_i,

  input  logic        redirect_i,      // registered redirect (has priority)
  input  logic [PcBits-1:2] redirect_pc_i,
  input  logic        redirect_out_i,  // its target is outside the window (valid with redirect_i)
  input  logic        redirect_hi_ok_i, // redirect_hi_i holds the target's high bits (not a
  input  logic [31:PcBits]  redirect_hi_i,  // fall-through, whose are zero)
  input  logic        predict_i,       // decode's predicted-taken jump or branch, first cycle
  input  logic [PcBits-1:2] predict_pc_i,  // its target (registered; execute corrects one outside)

  output logic        instr_valid_o,
  output logic [31:0] instr_o,         // an access fault reads as 0x00000017 (auipc x0, 0)
  output logic        instr_err_o,     // instruction access fault (rsp_err, or outside the window)
  output logic [31:2] instr_pc_o,
  output logic [PcBits-1:2] instr_npc_o,  // instr_pc_o + 4 (inside the window: no carry out)
  input  logic        instr_ready_i    // decode takes the instruction this cycle
);

  logic [PcBits-1:2] req_pc_q;   // address being requested
  logic [PcBits-1:2] head_pc_q;  // PC of the instruction at the decode interface
  logic [31:PcBits]  head_hi_q;  // its high bits: zero but after an outside redirect
  logic [PcBits-1:2] pend_pc_q;  // redirect target waiting behind a stuck request
  logic        pend_q;
  logic        out_q;          // the last redirect went outside the window: no requests
  logic        fault_q;        // hand decode faults: out_q, or the head is the window's last word
  logic        stuck_q;        // the request presented last cycle was not accepted
  logic [1:0]  in_flight_q;    // accepted requests without a response yet
  logic [1:0]  discard_q;      // how many of those are stale
  logic [1:0]  count_q;        // buffered instructions
  logic        rd_ptr_q, wr_ptr_q;
  logic [32:0] buf_q [2];      // {err, instr}

  logic [2:0]  occupancy;
  logic        req_accepted, req_waiting, rsp_keep, rsp_drop, bypass, flush;
  logic        buf_empty, consume, push, pop;
  logic [PcBits-1:2] req_addr, flush_pc;
  logic [31:0] rsp_instr;

  assign occupancy        = {1'b0, in_flight_q} + {1'b0, count_q};
  assign bypass           = flush && !stuck_q;
  assign req_addr         = bypass ? flush_pc : req_pc_q;
  // (After an outside redirect a request still waiting for ready stays; no new one goes out.)
  assign ibus_req_valid_o = (occupancy < 3'd2) && (!out_q || stuck_q);
  assign ibus_req_addr_o  = 32'({req_addr, 2'b00});
  assign req_accepted     = ibus_req_valid_o && ibus_req_ready_i;
  assign req_waiting      = ibus_req_valid_o && !ibus_req_ready_i;
  assign rsp_drop         = ibus_rsp_valid_i && (discard_q != 2'd0);
  assign rsp_keep         = ibus_rsp_valid_i && (discard_q == 2'd0) && !out_q;
  assign flush            = redirect_i || predict_i;
  assign flush_pc         = redirect_i ? redirect_pc_i : predict_pc_i;

  // A faulting fetch is handed on as AUIPC x0, 0, whose result (PC + 0, from the core's target
  // adder) is the PC for mtval (the bus returns rdata = 0 with an error); instr_err_o makes it trap.
  assign rsp_instr = ibus_rsp_rdata_i | (ibus_rsp_err_i ? 32'h0000_0017 : 32'h0);

  assign buf_empty     = (count_q == 2'd0);
  // A fault is handed over as a faulting fetch's word and flag, from fault_q directly (a flip-flop,
  // so the instruction multiplexer gains an input but no LUT level before it).
  assign instr_valid_o = fault_q || !buf_empty || rsp_keep;
  assign instr_o       = fault_q ? 32'h0000_0017 : (buf_empty ? rsp_instr : buf_q[rd_ptr_q][31:0]);
  assign instr_err_o   = fault_q || (buf_empty ? ibus_rsp_err_i : buf_q[rd_ptr_q][32]);
  assign instr_pc_o    = {head_hi_q, head_pc_q};
  assign instr_npc_o   = head_pc_q + (PcBits - 2)'(1);
  assign consume       = instr_valid_o && instr_ready_i;
  assign pop           = consume && !buf_empty;
  assign push          = rsp_keep && !(buf_empty && consume);

  logic [1:0] in_flight_d;
  assign in_flight_d = in_flight_q + {1'b0, req_accepted} - {1'b0, ibus_rsp_valid_i};

  // The head's next PC and whether the next cycle hands decode a fault, registered so that
  // fault_q reaches the instruction multiplexer straight from a flip-flop. The last-word test is
  // made on each candidate (kept), so the hand-shake (consume) only chooses at the end.
  logic [PcBits-1:2] head_pc_d;
  logic              out_d, flush_out, fault_d;
  (* keep *) logic   last_flush, last_next, last_head;
  assign flush_out  = redirect_i && redirect_out_i;
  assign head_pc_d  = flush ? flush_pc : (consume ? instr_npc_o : head_pc_q);
  assign out_d      = flush ? flush_out : out_q;
  assign last_flush = &flush_pc;
  assign last_next  = &instr_npc_o;
  assign last_head  = &head_pc_q;
  assign fault_d    = flush ? (flush_out || last_flush) : (out_q || (consume ? last_next : last_head));

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      head_pc_q   <= BootAddr[PcBits-1:2];
      head_hi_q   <= '0;
      pend_pc_q   <= BootAddr[PcBits-1:2];
      pend_q      <= 1'b0;
      out_q       <= 1'b0;
      fault_q     <= 1'b0;
      stuck_q     <= 1'b0;
      in_flight_q <= 2'd0;
      discard_q   <= 2'd0;
      count_q     <= 2'd0;
      rd_ptr_q    <= 1'b0;
      wr_ptr_q    <= 1'b0;
    end else begin
      in_flight_q <= in_flight_d;
      stuck_q     <= req_waiting;
      out_q       <= out_d;
      fault_q     <= fault_d;
      head_pc_q   <= head_pc_d;
      // Taken from every redirect that carries them, so no clear is needed: they are zero for a
      // target inside the window, and a fall-through or a predicted jump comes only from an
      // instruction inside it, while they are already zero (after an outside redirect the next
      // redirect is its fault's trap). A clear beside the reset cost 14 LUT4.
      if (redirect_i && redirect_hi_ok_i) begin
        head_hi_q <= redirect_hi_i;
      end
      if (flush) begin
        // Every request in flight after this cycle is stale, except one for the new address.
        discard_q <= in_flight_d - {1'b0, bypass && req_accepted};
        count_q   <= 2'd0;
        rd_ptr_q  <= 1'b0;
        wr_ptr_q  <= 1'b0;
        // A request waiting for ready keeps its address: the new one waits in pend_pc_q.
        pend_q    <= !bypass && req_waiting;
        if (!bypass && req_waiting) begin
          pend_pc_q <= flush_pc;
        end
      end else begin
        discard_q <= discard_q - {1'b0, rsp_drop} + {1'b0, pend_q && req_accepted};
        count_q   <= count_q + {1'b0, push} - {1'b0, pop};
        if (push) begin
          wr_ptr_q <= ~wr_ptr_q;
        end
        if (pop) begin
          rd_ptr_q <= ~rd_ptr_q;
        end
        if (req_accepted) begin
          pend_q   <= 1'b0;
        end
      end
    end
  end

  // The next request address as base + increment, one incrementer for every case: after a
  // redirect, its target, plus one if the bypassed request was accepted; otherwise the pending
  // target or the next word once a request is accepted. The base does not depend on the bus
  // hand-shake, only the increment (the carry-in) and the enable do: with the hand-shake choosing
  // the base in front of the carry chain, seed 2 reached 26.8 MHz. Two incrementers (the target's
  // and the request PC's) cost 43 LUT4 more.
  logic [PcBits-1:2] req_base;
  logic        req_inc, req_load;
  assign req_base = flush ? flush_pc : (pend_q ? pend_pc_q : req_pc_q);
  assign req_inc  = flush ? (bypass && req_accepted) : (!pend_q && req_accepted);
  assign req_load = flush ? (bypass || !req_waiting) : req_accepted;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      req_pc_q <= BootAddr[PcBits-1:2];
    end else if (req_load) begin
      // (Past the window's last word the address wraps: those words are behind its fault.)
      req_pc_q <= req_base + (PcBits - 2)'(req_inc);
    end
  end

  always_ff @(posedge clk_i) begin
    if (push && !flush) begin
      buf_q[wr_ptr_q] <= {ibus_rsp_err_i, rsp_instr};
    end
  end

endmodule
