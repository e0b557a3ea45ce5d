// Machine-mode CSRs, the cycle and instret counters, and the trap/mret state updates.
// Implemented: mstatus (MIE, MPIE; MPP reads 3), misa, mie/mip (read 0: no interrupt sources),
// mtvec (direct mode only), mscratch, mepc, mcause, mtval, mcycle(h), minstret(h), the read-only
// user aliases cycle(h)/instret(h) and mvendorid/marchid/mimpid/mhartid/mconfigptr (read 0);
// mstatush and the mhpm counters and event selectors read 0 and ignore writes (the decoder's
// CsrZero).
// mtvec holds addresses inside the executable window only (WARL: its bits 31:PcBits read 0).
module htx_cpu_csr #(
  parameter int unsigned PcBits = 18
) (
  input  logic                    clk_i,
  input  logic                    rst_ni,
  // CSR instruction in execute
  input  htx_cpu_pkg::csr_sel_e   sel_i,
  input  logic                    read_i,    // a CSR instruction is in execute (else rdata_o = 0)
  output logic [31:0]             rdata_o,
  input  logic                    we_i,      // commit the CSR write this cycle
  input  logic [1:0]              op_i,      // funct3[1:0]: 01 write, 10 set, 11 clear
  input  logic [31:0]             src_i,     // rs1 value or zero-extended uimm
  // instruction counting
  input  logic                    retire_i,   // an instruction leaves write-back without a fault
  output logic                    counting_o, // a retirement is still being added to minstret
  // traps
  input  logic                    trap_i,
  input  htx_cpu_pkg::exc_cause_e cause_i,
  input  logic [31:2]             trap_pc_i,
  input  logic [31:0]             tval_i,
  input  logic                    mret_i,
  output logic [PcBits-1:2]       mtvec_o,
  output logic [31:2]             mepc_o
);

  localparam logic [31:0] MisaValue = 32'h4000_1100;  // MXL=32, I, M

  logic        mie_q, mpie_q;
  logic [PcBits-1:2] mtvec_q;
  logic [31:2]       mepc_q;
  logic [3:0]  mcause_q;
  logic [31:0] mtval_q, mscratch_q;
  // Public so simulation harnesses can report the counts without a port.
  logic [63:0] cycle_q   /* verilator public_flat_rd */;
  logic [63:0] instret_q /* verilator public_flat_rd */;
  logic        retire_q, instret_carry, unused_cycle_carry;

  // The read value as an AND-OR of the selected registers, zero unless read_i: execute ORs it with
  // its other multi-cycle results instead of multiplexing once more.
  function automatic logic [31:0] pick(input logic en, input logic [31:0] v);
    pick = {32{en}} & v;
  endfunction
  logic [31:0] rdata_raw;
  assign rdata_raw = pick(sel_i == htx_cpu_pkg::CsrMstatus, {19'b0, 2'b11, 3'b0, mpie_q, 3'b0, mie_q, 3'b0}) |
                     pick(sel_i == htx_cpu_pkg::CsrMisa, MisaValue) |
                     pick(sel_i == htx_cpu_pkg::CsrMtvec, 32'({mtvec_q, 2'b00})) |
                     pick(sel_i == htx_cpu_pkg::CsrMscratch, mscratch_q) |
                     pick(sel_i == htx_cpu_pkg::CsrMepc, {mepc_q, 2'b00}) |
                     pick(sel_i == htx_cpu_pkg::CsrMcause, {28'b0, mcause_q}) |
                     pick(sel_i == htx_cpu_pkg::CsrMtval, mtval_q) |
                     pick(sel_i == htx_cpu_pkg::CsrCycle, cycle_q[31:0]) |
                     pick(sel_i == htx_cpu_pkg::CsrCycleh, cycle_q[63:32]) |
                     pick(sel_i == htx_cpu_pkg::CsrInstret, instret_q[31:0]) |
                     pick(sel_i == htx_cpu_pkg::CsrInstreth, instret_q[63:32]);
  assign rdata_o = pick(read_i, rdata_raw);

  logic [31:0] wdata;
  always_comb begin
    unique case (op_i)
      2'b01:   wdata = src_i;
      2'b10:   wdata = rdata_raw | src_i;
      default: wdata = rdata_raw & ~src_i;
    endcase
  end

  logic wr_cycle, wr_cycleh, wr_instret, wr_instreth;
  assign wr_cycle    = we_i && (sel_i == htx_cpu_pkg::CsrCycle);
  assign wr_cycleh   = we_i && (sel_i == htx_cpu_pkg::CsrCycleh);
  assign wr_instret  = we_i && (sel_i == htx_cpu_pkg::CsrInstret);
  assign wr_instreth = we_i && (sel_i == htx_cpu_pkg::CsrInstreth);

  // A counter write is registered and lands one cycle after the CSR instruction executes (so the
  // late write enable never enters a carry chain); the written half takes the value instead of
  // counting in that cycle and the other half counts on. The next CSR instruction can execute two
  // cycles after the writer at the earliest (it waits for write-back to empty and for counting_o),
  // so it reads what was written. A retirement is added one cycle after it is reported, and a
  // carry into the high half one cycle after the low half wraps (htx_counter64), so each 32-bit
  // carry chain starts at a flip-flop. The pipeline does not count the instruction that writes
  // minstret(h), and runs a CSR instruction only when write-back is empty and counting_o is low, so
  // instret_q is exact when it is read and no retirement coincides with a write. A read of cycleh
  // in the one cycle after the low half wraps sees the old high half; the usual hi, lo, hi read
  // sequence still returns a consistent value.
  logic        wr_cycle_q, wr_cycleh_q, wr_instret_q, wr_instreth_q;
  logic [31:0] wdata_q;
  assign counting_o = retire_q || instret_carry || wr_instret_q || wr_instreth_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      retire_q      <= 1'b0;
      wr_cycle_q    <= 1'b0;
      wr_cycleh_q   <= 1'b0;
      wr_instret_q  <= 1'b0;
      wr_instreth_q <= 1'b0;
    end else begin
      retire_q      <= retire_i;
      wr_cycle_q    <= wr_cycle;
      wr_cycleh_q   <= wr_cycleh;
      wr_instret_q  <= wr_instret;
      wr_instreth_q <= wr_instreth;
    end
  end

  always_ff @(posedge clk_i) begin
    wdata_q <= wdata;
  end

  htx_counter64 u_cycle (
    .clk_i,
    .rst_ni,
    .inc_i           (1'b1),
    .wr_lo_i         (wr_cycle_q),
    .wr_hi_i         (wr_cycleh_q),
    .wdata_i         (wdata_q),
    .count_o         (cycle_q),
    .carry_pending_o (unused_cycle_carry)
  );

  htx_counter64 u_instret (
    .clk_i,
    .rst_ni,
    .inc_i           (retire_q),
    .wr_lo_i         (wr_instret_q),
    .wr_hi_i         (wr_instreth_q),
    .wdata_i         (wdata_q),
    .count_o         (instret_q),
    .carry_pending_o (instret_carry)
  );

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      mie_q    <= 1'b0;
      mpie_q   <= 1'b0;
      mtvec_q  <= '0;
      mcause_q <= 4'b0;
    end else if (trap_i) begin
      mpie_q   <= mie_q;
      mie_q    <= 1'b0;
      mcause_q <= cause_i;
    end else if (mret_i) begin
      mie_q  <= mpie_q;
      mpie_q <= 1'b1;
    end else if (we_i) begin
      unique case (sel_i)
        htx_cpu_pkg::CsrMstatus: begin
          mie_q  <= wdata[3];
          mpie_q <= wdata[7];
        end
        htx_cpu_pkg::CsrMtvec:  mtvec_q  <= wdata[PcBits-1:2];
        htx_cpu_pkg::CsrMcause: mcause_q <= wdata[3:0];
        default: ;
      endcase
    end
  end

  always_ff @(posedge clk_i) begin
    if (trap_i) begin
      mepc_q  <= trap_pc_i;
      mtval_q <= tval_i;
    end else if (we_i) begin
      unique case (sel_i)
        htx_cpu_pkg::CsrMscratch: mscratch_q <= wdata;
        htx_cpu_pkg::CsrMepc:     mepc_q     <= wdata[31:2];
        htx_cpu_pkg::CsrMtval:    mtval_q    <= wdata;
        default: ;
      endcase
    end
  end

  assign mtvec_o = mtvec_q;
  assign mepc_o  = mepc_q;

endmodule
