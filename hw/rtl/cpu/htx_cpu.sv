// htx_cpu: RV32IM + Zicsr machine-mode core with a 4-stage pipeline.
//
//   F  fetch      htx_cpu_fetch issues word requests from a registered PC (one per clock). When
//                 decode takes an instruction, JAL and backward branches are predicted taken (BTFN)
//                 and redirect fetch; the register file read of the instruction's sources is issued.
//   D  decode     holds the instruction, decoded on its way in; forwards its operands (newest
//                 first: the instruction in E, the one in W, the register file) and registers the
//                 ALU operands, so E starts from flip-flops. Also precomputes every trap that does
//                 not depend on E's results.
//   E  execute    ALU, branch resolution, CSR access, the data bus request, MUL/DIV.
//   W  write-back waits for the data bus response of a load/store, writes the register file, and
//                 takes every trap: an access fault of its own load/store, or an instruction that
//                 E found trapping and handed over with its mtval as the result.
//
// Timing rules (docs/cpu.md): the ALU's results never feed the stall or hand-over logic; those are
// decided from registered state and the bus handshakes only. E's adder/logic result is forwarded
// into D; results that come late in E (shifts, links, CSR reads, MUL/DIV) are forwarded from W one
// cycle later. Redirects decided in E or W are registered: fetch follows one cycle later and the
// wrong-path instructions then in D and E are squashed.
//
// E only acts (bus request, CSR write, redirect, hand-over to W) in a cycle in which W completes
// without a trap, so a trap in W cancels everything younger: traps are precise. Taking every
// trap in W gives mepc and mtval one source each (W's PC and result registers).
//
// Instructions execute from the window [0, 2^PcBits - 4] (docs/cpu.md, "Executable window"): a
// fetch outside it is an instruction access fault, as a bus error on the fetch would be, with mepc
// and mtval the full address. Only fetch's and the redirect's PC logic is PcBits wide.
module htx_cpu #(
  parameter logic [31:0] ResetVector = 32'h0000_0000,
  parameter int unsigned PcBits      = 18
) (
  input  logic        clk_i,
  input  logic        rst_ni,

  output logic        ibus_req_valid_o,
  input  logic        ibus_req_ready_i,
  output logic [31:0] ibus_req_addr_o,
  output logic        ibus_req_we_o,
  output logic [3:0]  ibus_req_be_o,
  output logic [31:0] ibus_req_wdata_o,
  input  logic        ibus_rsp_valid_i,
  input  logic [31:0] ibus_rsp_rdata_i,
  input  logic        ibus_rsp_err_i,

  output logic        dbus_req_valid_o,
  input  logic        dbus_req_ready_i,
  output logic [31:0] dbus_req_addr_o,
  output logic        dbus_req_we_o,
  output logic [3:0]  dbus_req_be_o,
  output logic [31:0] dbus_req_wdata_o,
  input  logic        dbus_rsp_valid_i,
  input  logic [31:0] dbus_rsp_rdata_i,
  input  logic        dbus_rsp_err_i
);

  // The window must hold at least the reset vector's word and its last (faulting) word.
  if (PcBits < 3 || PcBits > 31 || ResetVector[31:2] >= (30'(1) << (PcBits - 2)) - 30'(1)) begin : g_bad_window
    $error("htx_cpu: PcBits must be 3 to 31 with the reset vector below the window's last word");
  end

  // ------------------------------------------------------------------------------------------
  // Fetch
  logic        redirect_q, d_redirect;
  logic [PcBits-1:2] redirect_pc_q, redirect_npc_q;
  logic [31:PcBits]  redirect_hi_q;  // the redirect target's high bits: not zero if outside
  logic [31:0] d_target_q;  // branch/JAL target, PC + immediate, added as D takes the instruction
  logic        redirect_seq_q;
  logic        f_valid, f_err;
  logic [31:0] f_instr;
  logic [31:2] f_pc;
  logic [PcBits-1:2] f_npc;
  logic        f_take;   // D takes the fetch output this cycle

  // A fall-through (redirect_seq_q) is inside the window: the window's last word never executes.
  logic redirect_out;
  assign redirect_out = !redirect_seq_q && (redirect_hi_q != '0);

  htx_cpu_fetch #(.BootAddr(ResetVector), .PcBits(PcBits)) u_fetch (
    .clk_i,
    .rst_ni,
    .ibus_req_valid_o,
    .ibus_req_ready_i,
    .ibus_req_addr_o,
    .ibus_rsp_valid_i,
    .ibus_rsp_rdata_i,
    .ibus_rsp_err_i,
    .redirect_i    (redirect_q),
    .redirect_pc_i (redirect_seq_q ? redirect_npc_q : redirect_pc_q),
    .redirect_out_i(redirect_out),
    .redirect_hi_ok_i(!redirect_seq_q),
    .redirect_hi_i (redirect_hi_q),
    .predict_i     (d_redirect),
    .predict_pc_i  (d_target_q[PcBits-1:2]),
    .instr_valid_o (f_valid),
    .instr_o       (f_instr),
    .instr_err_o   (f_err),
    .instr_pc_o    (f_pc),
    .instr_npc_o   (f_npc),
    .instr_ready_i (f_take)
  );

  assign ibus_req_we_o    = 1'b0;
  assign ibus_req_be_o    = 4'b1111;
  assign ibus_req_wdata_o = 32'b0;

  // Static prediction: JAL and backward branches are taken, unless the target would be misaligned
  // (then E raises the trap). Decided as D takes the instruction (from a few instruction bits) and
  // acted on in D's first cycle, when the target is already a register (d_target_q).
  htx_cpu_pkg::fetch_dec_t f_dec, d_fdec_q;  // the decoder's record of f_instr, and D's copy
  htx_cpu_pkg::decoded_t   d_dec;            // D's record: the decode table's entry joined with d_fdec_q
  logic f_is_jal, f_is_branch, f_predict;
  logic [31:0] f_target;
  assign f_is_jal    = (f_instr[6:0] == 7'b1101111);
  assign f_is_branch = (f_instr[6:0] == 7'b1100011);
  assign f_predict   = !f_err && ((f_is_jal && !f_instr[21]) || (f_is_branch && f_instr[31] && !f_instr[8]));
  // The target is added as D takes the instruction, so that in D's first cycle it is a register
  // that fetch can put on the bus at once (a predicted-taken jump then costs one bubble, not two).
  // The adder also forms AUIPC's result (PC + its U-immediate, E's result from e_aux_q), so D's
  // operand a has no PC input. Its immediate is the decoder's, whose format comes from a few
  // opcode bits (one multiplexer for operand b and this adder: 27 LUT4 fewer than one each over
  // ten numberings, and every placement seed faster; a full opcode compare in front of the carry
  // chain had cost two LUT levels).
  assign f_target = {f_pc, 2'b00} + f_dec.imm;

  // ------------------------------------------------------------------------------------------
  // Pipeline registers
  logic        d_valid_q, d_err_q, d_pred_q;
  logic        d_jump_q;   // d_valid_q && d_pred_q && D's first cycle: redirect fetch now
  logic [24:15] d_instr_q;  // the source register fields (the rest is decoded into d_dec)
  logic [31:2] d_pc_q;
  logic [PcBits-1:2] d_npc_q;

  logic                    e_valid_q;
  htx_cpu_pkg::exec_t      e_q;
  logic [32:0]             e_a_q, e_b_q;                    // ALU operands (bit 32: see the ALU)
  logic [31:0]             e_rs1_q;                         // the multiplier's operand a (rs1)
  logic [31:0]             e_rs2_q, e_aux_q;                // store data, a JAL or branch target
  logic                    e_br_eq_q, e_br_inv_q;           // branch condition: use eq, invert
  logic [31:2]             e_pc_q;
  logic [PcBits-1:2]       e_npc_q;
  // A predicted jump or branch whose target is outside the window: fetch went to the target's low
  // bits, so execute redirects it as if mispredicted, with the target's high bits.
  logic                    e_pout_q;
  logic                    e_pred_q, e_xtrap_q, e_late_q, e_sub_q, e_fwd_q;
  logic                    e_left_q, e_arith_q, e_fast_q, e_slt_q, e_shift_q;
  logic                    e_mem_q, e_mul_q, e_div_q;
  htx_cpu_pkg::exc_cause_e e_cause_q;
  logic [1:0]              e_lo_q;     // address bits [1:0] of a load/store
  logic [4:0]              e_rb_q;     // rs2 field (the multiply fusion check)
  // A MUL-class instruction reads the product's high word. e_q.funct3 holds the same fact; as a
  // flip-flop of its own it lets the result multiplexer fold in (9 LUT4 fewer than the compare).
  logic                    e_high_q;
  logic                    e_auipc_q;  // AUIPC: the result is e_aux_q (PC + immediate)

  logic        w_valid_q, w_load_q, w_store_q, w_nocount_q;
  logic        w_xt_q;       // W holds an instruction that traps: w_result_q is its mtval
  htx_cpu_pkg::exc_cause_e w_cause_q;
  logic        w_reverse_q;  // w_result_q is a bit-reversed left shift
  logic        w_wr_q;       // W holds an instruction that writes a register (not x0, no trap)
  logic [4:0]  w_rd_q;
  htx_cpu_pkg::load_sel_t e_load_sel, w_load_sel_q;
  logic [31:0] w_result_q;   // result, or the address of a load/store
  logic [31:2] w_pc_q;

  // ------------------------------------------------------------------------------------------
  // Write-back
  logic        w_ready, w_fault, w_trap;
  logic [31:0] w_load_value;
  (* keep *) logic rf_we;
  logic [31:0] rf_wdata;

  logic        w_memwait_q;  // W holds a load or store: it waits for the data response
  assign w_ready  = !w_memwait_q || dbus_rsp_valid_i;
  assign w_fault  = w_memwait_q && dbus_rsp_valid_i && dbus_rsp_err_i;
  assign w_trap   = w_fault || w_xt_q;
  // (One LUT from the bus's response, kept so: the register file takes it half a cycle later.)
  assign rf_we    = w_wr_q && (!w_memwait_q || (dbus_rsp_valid_i && !dbus_rsp_err_i));
  // Everything but a load's value is known from W's flip-flops (a left shift's result is
  // reversed), so it is formed first and ORed in where the load's lanes end (w_load_value is 0
  // unless W holds a load).
  logic [31:0] w_other;
  always_comb begin
    for (int i = 0; i < 32; i++) begin
      w_other[i] = !w_load_q && (w_reverse_q ? w_result_q[31-i] : w_result_q[i]);
    end
  end
  assign rf_wdata = w_load_value | w_other;

  // ------------------------------------------------------------------------------------------
  // Register file: read when D takes an instruction; while D holds its instruction the register
  // file keeps reading D's own sources, so the read data reflects every write up to the previous
  // falling edge and only the write of D's current cycle (W's) has to be forwarded.
  logic        d_free;
  logic [31:0] rf_rdata_a, rf_rdata_b;

  htx_cpu_regfile u_regfile (
    .clk_i,
    .raddr_a_i (d_free_nr ? f_instr[19:15] : d_instr_q[19:15]),
    .raddr_b_i (d_free_nr ? f_instr[24:20] : d_instr_q[24:20]),
    .rdata_a_o (rf_rdata_a),
    .rdata_b_o (rf_rdata_b),
    .we_i      (rf_we),
    .waddr_i   (w_rd_q),
    .wdata_i   (rf_wdata)
  );

  // ------------------------------------------------------------------------------------------
  // Decode. The decoder works on fetch's output and D registers its record as it takes the
  // instruction (d_fdec_q); the decode table, read at the same edge from the same word's opcode and
  // funct3, holds the rest in block RAM and joins the two (d_dec), so D's logic starts from
  // flip-flops and the RAM's output register. The forwarding selects and the hazard check use the
  // raw register fields. (f_dec is declared with the target adder, its other user.)
  logic [4:0] d_ra, d_rb;  // source register fields

  htx_cpu_decoder u_decoder (
    .instr_i (f_instr),
    .dec_o   (f_dec)
  );
  htx_cpu_decode_table u_decode_table (
    .clk_i,
    .take_i  (d_free_nr),
    .instr_i (f_instr),
    .fdec_i  (d_fdec_q),
    .dec_o   (d_dec)
  );
  assign d_ra = d_instr_q[19:15];
  assign d_rb = d_instr_q[24:20];

  logic        e_live, e_accept;
  logic [31:0] e_fast_result;

  // Forwarding: E's adder/logic result, W's write data, the register file.
  logic fe_a, fe_b, fw_a, fw_b;
  // (Each compare starts from one registered enable; a squashed E or D makes the choice moot.)
  assign fe_a = e_valid_q && e_fwd_q && (e_q.rd == d_ra);
  assign fe_b = e_valid_q && e_fwd_q && (e_q.rd == d_rb);
  assign fw_a = w_wr_q && (w_rd_q == d_ra);
  assign fw_b = w_wr_q && (w_rd_q == d_rb);

  // The value from E comes last (end of the carry chain), so it enters at the final LUT level, and
  // W's write data (a load's lanes come straight from the bus) one level before it (_rest, kept
  // as separate signals so synthesis does not fold the later value deeper into the mux tree).
  (* keep *) logic [31:0] d_rs2_rest, d_a_rest;
  assign d_rs2_rest  = fw_b ? rf_wdata : rf_rdata_b;
  logic [31:0] d_rs2;
  assign d_rs2    = fe_b ? e_fast_result : d_rs2_rest;

  // A source written by the instruction in E whose result comes late (load, shift, link, CSR,
  // MUL/DIV) waits one cycle and then comes from W. W always completes when D moves on.
  // The compare uses registered fields only (E's destination, D's source fields and whether D
  // reads them). It was computed a cycle early, for whatever E's and D's registers would hold,
  // to keep it off the stall chain; compared in place it is 11 LUT4 smaller and the core placed
  // faster at every seed (2026-12-05).
  // A MUL-class instruction also waits for a source E would forward (its adder/logic result): its
  // correction terms below then take the sources' signs from W or the register file, not from the
  // end of E's carry chain, which had been a critical path (1,027 more cycles in `bench`).
  logic d_hazard, hz;
  assign hz       = (e_q.rd_we && e_late_q &&
                     ((d_dec.rs1_used && (e_q.rd == d_ra)) || (d_dec.rs2_used && (e_q.rd == d_rb)))) ||
                    (d_dec.mul && (fe_a || fe_b));
  assign d_hazard = e_live && hz;

  logic late_alu_d, late_d, sub_d;
  assign late_alu_d = d_dec.slt || d_dec.shift;
  assign late_d     = d_dec.auipc || d_dec.load || d_dec.jal || d_dec.jalr || d_dec.csr ||
                      d_dec.mul || d_dec.div || late_alu_d;
  assign sub_d      = d_dec.sub;

  // ALU operands, extended to 33 bits with the sign for a signed comparison (SLT, BLT, BGE) and
  // with zero otherwise; b is inverted for a subtraction.
  logic [31:0] d_a, d_b;
  logic        signed_d;
  assign d_a_rest = fw_a ? rf_wdata : rf_rdata_a;
  assign d_a      = fe_a ? e_fast_result : d_a_rest;
  // Operand b is the forwarded rs2 (the store data's multiplexer) or the immediate, one LUT level
  // after it with the inversion for a subtraction: a forwarding multiplexer of its own with the
  // late values at its last level cost 54 LUT4 more (2026-12-05).
  assign d_b      = d_dec.b_rs2 ? d_rs2 : d_dec.imm;
  // Operand b's extension bit for either value of the forwarded rs2's sign, so that the late sign
  // only selects (one LUT level after d_rs2, like the other bits).
  (* keep *) logic b_ext_0, b_ext_1;
  assign b_ext_0 = (d_dec.b_rs2 ? 1'b0 : (signed_d & d_dec.imm[31])) ^ sub_d;
  assign b_ext_1 = (d_dec.b_rs2 ? signed_d : (signed_d & d_dec.imm[31])) ^ sub_d;
  assign signed_d = d_dec.signed_cmp;

  // A MUL-class instruction's ALU operands are the two terms of its signed correction, corr =
  // (a < 0 ? b : 0) + (b < 0 ? a : 0) with a = rs1 signed unless MULHU and b = rs2 signed for MUL
  // and MULH: operand a is rs1 if rs2 is a negative signed operand and 0 otherwise, operand b is
  // rs2 if rs1 is a negative signed operand and 0 otherwise. E's adder then forms corr, inverted
  // for the multiplier's DSP (htx_cpu_mul), in place of a 4-way choice among 0, rs1, rs2 and their
  // sum in the unit (66 LUT4). The zeros are the operand flip-flops' synchronous resets, whose
  // conditions come from the sources' signs one LUT level after them (never E's result: a MUL
  // waits for it, above); the multiplier takes rs1 from e_rs1_q (its DSPs' input register).
  // Each reset is the OR of a part known from D's registers and a part that waits for the sign,
  // both kept apart so that the sign enters at the last LUT level (the decode table's entry and
  // funct7's flag would otherwise put a second level behind it).
  logic            zero_a, zero_b;
  (* keep *) logic zero_a_now, zero_b_now, zero_a_pos, zero_b_pos;
  assign zero_a_now = d_dec.a_zero || (d_dec.mul && d_dec.funct3[1]);
  assign zero_a_pos = d_dec.mul && !d_dec.funct3[1];
  assign zero_b_now = d_dec.mul && (d_dec.funct3[1:0] == 2'b11);
  assign zero_b_pos = d_dec.mul && (d_dec.funct3[1:0] != 2'b11);
  assign zero_a     = zero_a_now || (zero_a_pos && !d_rs2_rest[31]);
  assign zero_b     = zero_b_now || (zero_b_pos && !d_a_rest[31]);

  // Address bits [1:0] of a load, store or JALR target, for the misalignment checks. The two-bit
  // sum is formed for every forwarding source and the forwarding selects come last, so the
  // register compares and the trap logic behind them are not in series with the adder.
  logic [1:0] d_lo, lo_e, lo_w, lo_r;
  logic       d_misaligned;
  assign lo_e = e_fast_result[1:0] + d_dec.imm[1:0];
  assign lo_w = rf_wdata[1:0] + d_dec.imm[1:0];
  assign lo_r = rf_rdata_a[1:0] + d_dec.imm[1:0];
  assign d_lo = fe_a ? lo_e : fw_a ? lo_w : lo_r;
  always_comb begin
    unique case (d_dec.funct3[1:0])
      2'b00:   d_misaligned = 1'b0;
      2'b01:   d_misaligned = d_lo[0];
      default: d_misaligned = (d_lo != 2'b00);
    endcase
  end

  // Traps known before E (everything except a taken branch to a misaligned target). mtval comes
  // from E's adder (decode sets it up to produce the PC or 0 where that is the value), for a branch
  // or JAL from the target, and is 0 for an illegal instruction (allowed by the privileged spec; a
  // handler can read the instruction at mepc; this saves a 32-bit multiplexer).
  logic                    d_xtrap;
  htx_cpu_pkg::exc_cause_e d_cause;
  // The cause matters only when the instruction traps, so it is chosen as if the misalignment
  // checks fired: the late address bits (d_lo, behind D's forwarding) then reach only d_xtrap, not
  // the cause's priority chain (which was the critical path of two placement seeds).
  always_comb begin
    if (d_err_q) begin
      d_cause = htx_cpu_pkg::ExcInstrAccess;
    end else if (d_dec.illegal) begin
      d_cause = htx_cpu_pkg::ExcIllegal;
    end else if (d_dec.ecall) begin
      d_cause = htx_cpu_pkg::ExcEcallM;
    end else if (d_dec.ebreak) begin
      d_cause = htx_cpu_pkg::ExcBreakpoint;
    end else if (d_dec.jal || d_dec.jalr) begin
      d_cause = htx_cpu_pkg::ExcInstrMisaligned;
    end else if (d_dec.store) begin
      d_cause = htx_cpu_pkg::ExcStoreMisaligned;
    end else begin
      d_cause = htx_cpu_pkg::ExcLoadMisaligned;
    end
  end
  // (Bit 1 of a JAL's offset is instruction bit 21.)
  assign d_xtrap = d_err_q || d_dec.illegal || d_dec.ecall || d_dec.ebreak ||
                   (d_dec.jal && d_instr_q[21]) || (d_dec.jalr && d_lo[1]) ||
                   ((d_dec.load || d_dec.store) && d_misaligned);

  htx_cpu_pkg::exec_t d_exec;
  always_comb begin
    d_exec.mret    = d_dec.mret;
    d_exec.fencei  = d_dec.fencei;
    // (An illegal branch, JALR or CSR encoding is none of them in E: its result is its mtval, 0.)
    d_exec.branch  = d_dec.branch && !d_dec.illegal;
    d_exec.jal     = d_dec.jal;
    d_exec.jalr    = d_dec.jalr && !d_dec.illegal;
    d_exec.load    = d_dec.load;
    d_exec.store   = d_dec.store;
    d_exec.mul     = d_dec.mul;
    d_exec.csr     = d_dec.csr && !d_dec.illegal;
    d_exec.csr_we  = d_dec.csr_we;
    d_exec.csr_sel = d_dec.csr_sel;
    d_exec.funct3  = d_dec.funct3;
    d_exec.uimm    = d_dec.rs1;
    d_exec.rd      = d_dec.rd;
    d_exec.rd_we   = d_dec.rd_we;
    d_exec.alu_op  = d_dec.alu_op;
  end

  // Multiply fusion: a MUL-class instruction that enters E right behind another one with the same
  // source registers takes the other half of the product the unit already holds instead of
  // multiplying again (MUL and MULH, the RISC-V spec's recommended pair, in either order). The
  // unit computes MUL's high half as signed x signed, so a MUL pairs with MULH and with anything
  // before it; otherwise the signedness must match. A MUL that was itself fused (e_mul_q low)
  // left its predecessor's product in the unit, so a MULH after it pairs only if that MUL ran
  // (after MULHSU or MULHU the high half is not MULH's). The first one's destination cannot be a
  // source of the second here: that is a late-result hazard, which puts a bubble in E first.
  logic fuse_d, fuse_mode;
  assign fuse_mode = (d_dec.funct3[1:0] == 2'b00) || (d_dec.funct3[1:0] == e_q.funct3[1:0]) ||
                     ((e_q.funct3[1:0] == 2'b00) && e_mul_q && (d_dec.funct3[1:0] == 2'b01));
  assign fuse_d    = d_dec.mul && e_valid_q && e_q.mul && !e_xtrap_q && fuse_mode &&
                     (e_q.uimm == d_ra) && (e_rb_q == d_rb);

  logic d_live, d_go;
  assign d_live     = d_valid_q && !redirect_q;
  assign d_go       = d_live && e_accept && !d_hazard;
  assign d_free     = !d_live || d_go;
  assign d_redirect = d_jump_q && !redirect_q;

  // The same hand-over decisions assuming no registered redirect (_nr): where a redirect makes
  // the choice irrelevant (everything in D and E is squashed), these drive the wide enables and
  // the fetch hand-shake, which keeps redirect_q off the front of those paths.
  // e_accept_nr = w_ready && (!e_valid_q || (!w_fault && !csr_block && !e_wait)), arranged in two
  // LUT levels after the bus hand-shakes: W's part (acc_w, from one registered flag and the
  // response) and E's part (acc_e, from the request's ready), each kept as a separate signal.
  logic e_accept_nr, d_free_nr, e_block;
  (* keep *) logic acc_w, acc_e;
  assign e_block     = (e_q.csr && (w_valid_q || csr_counting)) || unit_wait_q;
  assign acc_w       = !w_memwait_q || (dbus_rsp_valid_i && (!e_valid_q || !dbus_rsp_err_i));
  assign acc_e       = !e_valid_q || (!e_block && (!e_mem || dbus_req_ready_i));
  assign e_accept_nr = acc_w && acc_e;
  assign d_free_nr   = !d_valid_q || (e_accept_nr && !(e_valid_q && hz));
  assign f_take      = d_free_nr && !redirect_q && !d_jump_q;


  // ------------------------------------------------------------------------------------------
  // Execute: ALU, branches
  logic [31:0] alu_sum, alu_late;
  logic        alu_eq, alu_lt;

  htx_cpu_alu u_alu (
    .op_i     (e_q.alu_op),
    .sub_i    (e_sub_q),
    .left_i   (e_left_q),
    .arith_i  (e_arith_q),
    .invert_i (e_q.mul),     // the multiplier's ~corr (below)
    .a_i      (e_a_q),
    .b_i      (e_b_q),
    .fast_o   (e_fast_result),
    .late_o   (alu_late),
    .sum_o    (alu_sum),
    .eq_o     (alu_eq),
    .lt_o     (alu_lt)
  );

  // The branch condition arrives last (from the end of the carry chain). Everything that depends
  // on it is computed for both outcomes (_t taken, _n not taken) from registered state and the
  // handshakes, and the condition selects in one LUT level; the keep attributes stop synthesis
  // from merging the condition deeper into that logic.
  (* keep *) logic br_cond;
  assign br_cond = e_br_inv_q ^ (e_br_eq_q ? alu_eq : alu_lt);

  // ------------------------------------------------------------------------------------------
  // Execute: traps
  htx_cpu_pkg::exc_cause_e e_cause;
  assign e_cause = e_xtrap_q ? e_cause_q : htx_cpu_pkg::ExcInstrMisaligned;

  // ------------------------------------------------------------------------------------------
  // Execute: memory, multiply, divide, CSR
  logic        e_can_go, e_mem, e_mul, e_div, e_wait, e_done;
  logic        mul_busy, div_busy, csr_counting;
  logic        mul_done_next, div_done_next;
  // A trap's CSR updates are applied one cycle after W takes it (together with the registered
  // redirect); nothing can read those CSRs in between, because the instruction then in E is squashed.
  // trap_pc_q and trap_tval_q are plain copies of W's PC and result.
  logic                    trap_q;
  htx_cpu_pkg::exc_cause_e trap_cause_q;
  logic [31:2]             trap_pc_q;
  logic [31:0]             trap_tval_q;
  logic [31:0] mul_result, div_result, csr_rdata;
  logic [PcBits-1:2] mtvec;
  logic [31:2]       mepc;

  // E holds a live instruction unless it entered on the wrong path while a redirect was decided.
  // A CSR instruction waits until W is empty and its retirement is counted, so the counters it
  // reads are exact.
  assign e_live   = e_valid_q && !redirect_q;
  assign e_can_go = e_live && w_ready && !w_trap && !(e_q.csr && (w_valid_q || csr_counting));
  assign e_mem    = e_mem_q;  // (load || store) && no early trap, registered for the stall logic
  assign e_mul    = e_mul_q;
  assign e_div    = e_div_q;

  htx_cpu_mul u_mul (
    .clk_i,
    .rst_ni,
    .start_i  (e_can_go && e_mul && !mul_busy),
    .high_i   (e_high_q),
    .a_i      (e_rs1_q),
    .b_i      (e_rs2_q),
    .ncorr_i  (alu_sum),     // ~(a + b): a MUL-class instruction's operands are corr's terms
    .busy_o   (mul_busy),
    .done_next_o (mul_done_next),
    .result_o (mul_result)
  );

  htx_cpu_div u_div (
    .clk_i,
    .rst_ni,
    .start_i  (e_can_go && e_div && !div_busy),
    .kill_i   (w_fault),
    .clear_i  (e_accept_nr),
    .op_i     (e_q.funct3[1:0]),
    .a_i      (e_rs1_q),
    .b_i      (e_rs2_q),
    .b_zero_i (alu_eq),      // 0 + rs2 == 0: decode clears a divide's operand a
    .busy_o   (div_busy),
    .done_next_o (div_done_next),
    .result_o (div_result)
  );

  // E's multiply or divide is still working, kept in a flip-flop computed a cycle early from what
  // E will hold and the units' done_next_o, so the stall chain starts from one flip-flop.
  logic unit_wait_q, unit_wait_d, mul_next, div_next;
  // (A decoded MUL or DIV is legal and traps before E only on an instruction access fault, so
  // d_err_q stands for d_xtrap here and keeps the misalignment checks off this path.)
  assign mul_next    = e_accept_nr ? (d_dec.mul && !d_err_q && !fuse_d) : e_mul_q;
  assign div_next    = e_accept_nr ? (d_dec.div && !d_err_q) : e_div_q;
  assign unit_wait_d = (mul_next && !mul_done_next) || (div_next && !div_done_next);
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      unit_wait_q <= 1'b0;
    end else begin
      unit_wait_q <= unit_wait_d;
    end
  end
  assign e_wait      = (e_mem && !dbus_req_ready_i) || unit_wait_q;
  assign e_done      = e_can_go && !e_wait;

  // Outcomes of E for both branch outcomes (see br_cond): whether the instruction handed to W
  // traps there (xt_*: an early trap, or a taken branch to a misaligned target), redirect (W's
  // trap first), and whether the redirect goes to the fall-through PC.
  logic br_misaligned, e_jump, e_ctl_n, e_ctl_t;
  assign br_misaligned = e_q.branch && e_aux_q[1];
  assign e_jump        = e_q.jal || e_q.jalr;
  assign e_ctl_n       = !e_xtrap_q && (e_q.mret || e_q.fencei || (e_jump != e_pred_q) || e_pout_q);
  assign e_ctl_t       = !e_xtrap_q && !br_misaligned &&
                         (e_q.mret || e_q.fencei || ((e_jump || e_q.branch) != e_pred_q) || e_pout_q);
  (* keep *) logic xt_t, xt_n, redir_t, redir_n, seq_t, seq_n;
  assign xt_n     = e_done && e_xtrap_q;
  assign xt_t     = e_done && (e_xtrap_q || br_misaligned);
  assign redir_n  = w_trap || (e_done && e_ctl_n);
  assign redir_t  = w_trap || (e_done && e_ctl_t);
  assign seq_n    = !w_trap && (e_q.fencei || e_q.branch);
  assign seq_t    = !w_trap && e_q.fencei;

  logic csr_we, csr_instret_we;
  assign csr_we         = e_done && !e_xtrap_q && e_q.csr && e_q.csr_we;
  assign csr_instret_we = (e_q.csr_sel == htx_cpu_pkg::CsrInstret) ||
                          (e_q.csr_sel == htx_cpu_pkg::CsrInstreth);

  htx_cpu_csr #(.PcBits(PcBits)) u_csr (
    .clk_i,
    .rst_ni,
    .sel_i     (e_q.csr_sel),
    .read_i    (e_q.csr),
    .rdata_o   (csr_rdata),
    .we_i      (csr_we),
    .op_i      (e_q.funct3[1:0]),
    .src_i     ({e_a_q[31:5], e_a_q[4:0] | (e_q.uimm & {5{e_q.funct3[2]}})}),
    .retire_i  (w_valid_q && w_ready && !w_trap && !w_nocount_q),
    .counting_o(csr_counting),
    .trap_i    (trap_q),
    .cause_i   (trap_cause_q),
    .trap_pc_i (trap_pc_q),
    .tval_i    (trap_tval_q),
    .mret_i    (e_done && !e_xtrap_q && e_q.mret),
    .mtvec_o   (mtvec),
    .mepc_o    (mepc)
  );

  // The shifter (eight LUT levels from E's registers) enters at the last LUT level, the adder/logic
  // result and SLT (end of the carry chain) one level before it; the other results are chosen
  // first (kept as separate signals so synthesis does not fold the late values deeper into the
  // mux tree).
  //
  // A trapping instruction goes to W with its mtval as the result: the address of a misaligned
  // load, store or JALR target (the adder), the target of a JAL or branch (e_aux_q), the PC of a
  // fetch that faulted (AUIPC x0, 0: PC + 0 in e_aux_q), 0 for an illegal instruction (no kind is
  // selected) and for ECALL and EBREAK (the adder's 0 + 0).
  (* keep *) logic [31:0] e_result_rest, e_result_early;
  logic [31:0] e_result;
  logic        sel_link, sel_aux, sel_fast;
  assign sel_link = (e_q.jal || e_q.jalr) && !e_xtrap_q;
  assign sel_aux  = e_q.branch || e_auipc_q || (e_q.jal && e_xtrap_q);
  assign sel_fast = e_fast_q || (e_q.jalr && e_xtrap_q);
  // An AND-OR of the registered one-hot kinds (csr_rdata is already 0 unless a CSR instruction,
  // div_result unless E holds a division that has finished).
  assign e_result_rest  = ({32{sel_link}} & 32'({e_npc_q, 2'b00})) | ({32{sel_aux}} & e_aux_q) |
                          csr_rdata | ({32{e_q.mul}} & mul_result) | div_result;
  assign e_result_early = sel_fast ? e_fast_result :               // fast: includes the address
                          e_slt_q  ? {31'b0, alu_lt} : e_result_rest;
  assign e_result       = e_shift_q ? alu_late : e_result_early;

  logic [3:0]  lsu_be;
  logic [31:0] lsu_wdata;

  htx_cpu_lsu u_lsu (
    .req_size_i   (e_q.funct3[1:0]),
    .req_offset_i (e_lo_q),
    .req_data_i   (e_rs2_q),
    .req_be_o     (lsu_be),
    .req_wdata_o  (lsu_wdata),
    .req_load_i   (e_q.load),
    .req_signed_i (!e_q.funct3[2]),
    .req_sel_o    (e_load_sel),
    .rsp_sel_i    (w_load_sel_q),
    .rsp_rdata_i  (dbus_rsp_rdata_i),
    .rsp_value_o  (w_load_value)
  );

  // Data bus request: held stable while not accepted, because nothing it depends on can change
  // until E moves on.
  assign dbus_req_valid_o = e_can_go && e_mem;
  assign dbus_req_addr_o  = alu_sum;
  assign dbus_req_we_o    = e_q.store;
  assign dbus_req_be_o    = lsu_be;
  assign dbus_req_wdata_o = lsu_wdata;

  // ------------------------------------------------------------------------------------------
  // Redirects and stage hand-over
  assign e_accept = w_ready && (!e_live || e_done);

  // The redirect target is registered as two candidates and chosen in the next cycle, so the
  // branch condition only drives one flip-flop here: the fall-through PC (a branch that is not
  // taken, FENCE.I) or the other target.
  logic [31:2] late_pc;
  always_comb begin
    if (w_trap) begin
      late_pc = 30'(mtvec);
    end else if (e_q.mret) begin
      late_pc = mepc;
    end else if (e_q.jalr) begin
      late_pc = alu_sum[31:2];
    end else begin
      late_pc = e_aux_q[31:2];
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      redirect_q <= 1'b0;
      trap_q     <= 1'b0;
    end else begin
      redirect_q <= br_cond ? redir_t : redir_n;
      trap_q     <= w_trap;
    end
  end

  always_ff @(posedge clk_i) begin
    redirect_pc_q <= late_pc[PcBits-1:2];
    redirect_hi_q <= late_pc[31:PcBits];
    redirect_npc_q <= e_npc_q;
    redirect_seq_q <= br_cond ? seq_t : seq_n;
    trap_cause_q  <= w_fault ? (w_store_q ? htx_cpu_pkg::ExcStoreAccess : htx_cpu_pkg::ExcLoadAccess)
                             : w_cause_q;
    trap_pc_q     <= w_pc_q;
    trap_tval_q   <= w_result_q;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      d_valid_q  <= 1'b0;
      e_valid_q  <= 1'b0;
      w_valid_q  <= 1'b0;
      w_wr_q     <= 1'b0;
      w_xt_q     <= 1'b0;
      d_jump_q   <= 1'b0;
      w_memwait_q <= 1'b0;
    end else begin
      if (d_free) begin
        d_valid_q <= f_take && f_valid;
      end
      // (When D takes an instruction it is free, so it holds exactly what fetch hands over.)
      d_jump_q  <= f_take && f_valid && f_predict;
      e_valid_q <= e_accept ? d_go : (e_valid_q && !redirect_q);
      if (w_ready) begin
        w_valid_q <= e_done;
        w_xt_q    <= br_cond ? xt_t : xt_n;
        w_wr_q    <= e_done && e_q.rd_we && !e_xtrap_q;
        w_memwait_q <= e_done && e_mem_q;
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (d_free_nr) begin
      d_instr_q  <= f_instr[24:15];
      d_fdec_q   <= f_dec;
      d_target_q <= f_target;
      d_err_q    <= f_err;
      d_pc_q     <= f_pc;
      d_npc_q    <= f_npc;
      d_pred_q   <= f_predict;
    end
    if (e_accept_nr) begin
      e_q       <= d_exec;
      e_a_q     <= zero_a ? 33'b0 : {signed_d & d_a[31], d_a};
      e_b_q     <= zero_b ? 33'b0 : {d_rs2[31] ? b_ext_1 : b_ext_0, d_b ^ {32{sub_d}}};
      e_rs1_q   <= d_a;
      e_br_eq_q <= !d_dec.funct3[2];
      e_br_inv_q <= d_dec.funct3[0];
      e_rs2_q   <= d_rs2;
      e_aux_q   <= d_target_q;
      e_pc_q    <= d_pc_q;
      e_npc_q   <= d_npc_q;
      e_pred_q  <= d_pred_q;
      e_pout_q  <= d_pred_q && (d_target_q[31:PcBits] != '0);
      e_xtrap_q <= d_xtrap;
      e_mem_q   <= (d_dec.load || d_dec.store) && !d_xtrap;
      e_mul_q   <= mul_next;  // a fused one needs no unit cycles
      e_rb_q    <= d_rb;
      e_high_q  <= (d_dec.funct3[1:0] != 2'b00);
      e_div_q   <= div_next;
      e_cause_q <= d_cause;
      e_late_q  <= late_d;
      e_fwd_q   <= d_dec.rd_we && !late_d;
      e_sub_q   <= sub_d;
      e_auipc_q <= d_dec.auipc && !d_dec.illegal;
      e_left_q  <= d_dec.left;
      e_arith_q <= d_dec.arith;
      // (Not for an illegal instruction, whose result is its mtval 0, nor a branch, whose result
      // is its target for mtval.)
      e_fast_q  <= !(d_dec.auipc || late_alu_d || d_dec.jal || d_dec.jalr || d_dec.csr ||
                     d_dec.mul || d_dec.div || d_dec.branch || d_dec.illegal);
      e_slt_q   <= d_dec.slt && !d_dec.illegal;
      e_shift_q <= d_dec.shift && !d_dec.illegal;
      e_lo_q    <= d_lo;
    end
    if (w_ready) begin
      w_rd_q      <= e_q.rd;
      w_cause_q   <= e_cause;
      w_load_q    <= e_q.load;
      w_store_q   <= e_q.store;
      w_load_sel_q <= e_load_sel;
      // (A misaligned JALR's mtval is its target with bit 0 cleared.)
      w_result_q  <= {e_result[31:1], e_result[0] && !(e_q.jalr && e_xtrap_q)};
      w_reverse_q <= e_left_q;
      w_pc_q      <= e_pc_q;
      w_nocount_q <= e_q.csr && e_q.csr_we && csr_instret_we;
    end
  end

endmodule
