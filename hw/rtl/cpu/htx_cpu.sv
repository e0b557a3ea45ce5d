// htx_cpu: RV32IM + Zicsr machine-mode core with a 4-stage pipeline.
//
//   F  fetch      htx_cpu_fetch issues word requests from a registered PC (one per clock).
//   D  decode     the instruction arrives from the bus (or the fetch buffer); decoded, the register
//                 file read is issued (block RAM, synchronous), JAL and backward branches are
//                 predicted taken and redirect fetch (BTFN).
//   E  execute    operands (register file, forwarded from W or from the last register write), ALU,
//                 branch resolution, CSR access, traps, the data bus request, multi-cycle MUL/DIV.
//   W  write-back waits for the data bus response of a load/store, writes the register file.
//
// E only acts (bus request, CSR write, trap, redirect, hand-over to W) in a cycle in which W
// completes without an access fault, so a faulting load/store in W can still cancel everything
// younger: traps are precise. A register written by a load in W cannot be used by E in the same
// cycle (load-use: one stall). Redirects decided in E or W (mispredicted branch, JALR, trap, MRET,
// FENCE.I, access fault) are registered for timing: fetch follows them one cycle later and the
// wrong-path instruction that entered E meanwhile is squashed. See docs/cpu.md.
module htx_cpu #(
  parameter logic [31:0] ResetVector = 32'h0000_0000
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

  // ------------------------------------------------------------------------------------------
  // Fetch
  logic        redirect;
  logic [31:2] redirect_pc;
  logic        f_valid, f_err;
  logic [31:0] f_instr, f_pc;
  logic        d_advance;

  htx_cpu_fetch #(.BootAddr(ResetVector)) u_fetch (
    .clk_i,
    .rst_ni,
    .ibus_req_valid_o,
    .ibus_req_ready_i,
    .ibus_req_addr_o,
    .ibus_rsp_valid_i,
    .ibus_rsp_rdata_i,
    .ibus_rsp_err_i,
    .redirect_i    (redirect),
    .redirect_pc_i (redirect_pc),
    .instr_valid_o (f_valid),
    .instr_o       (f_instr),
    .instr_err_o   (f_err),
    .instr_pc_o    (f_pc),
    .instr_ready_i (d_advance)
  );

  assign ibus_req_we_o    = 1'b0;
  assign ibus_req_be_o    = 4'b1111;
  assign ibus_req_wdata_o = 32'b0;

  // ------------------------------------------------------------------------------------------
  // Decode
  htx_cpu_pkg::decoded_t d_dec;
  logic [31:0] d_target;
  logic        d_predict;

  htx_cpu_decoder u_decoder (
    .instr_i (f_instr),
    .dec_o   (d_dec)
  );

  // Static prediction: JAL and backward branches taken, unless the target would trap.
  assign d_target  = f_pc + d_dec.imm;
  assign d_predict = !f_err && (d_dec.jal || (d_dec.branch && d_dec.imm[31])) && !d_target[1];

  // ------------------------------------------------------------------------------------------
  // Pipeline registers
  logic                  e_valid_q;
  htx_cpu_pkg::decoded_t e_q;
  logic [31:0]           e_pc_q, e_target_q;
  logic                  e_pred_q, e_ferr_q;

  logic        w_valid_q, w_rd_we_q, w_load_q, w_mem_q, w_store_q;
  logic [4:0]  w_rd_q;
  logic [2:0]  w_funct3_q;
  logic [31:0] w_result_q;   // result, or the address of a load/store
  logic [31:2] w_pc_q;

  // The last register-file write, which a read issued in the same cycle did not see.
  logic        lw_valid_q;
  logic [4:0]  lw_rd_q;
  logic [31:0] lw_data_q;

  // ------------------------------------------------------------------------------------------
  // Write-back
  logic        w_ready, w_fault;
  logic [31:0] w_load_value;
  logic        rf_we;
  logic [31:0] rf_wdata;

  assign w_ready  = !w_valid_q || !w_mem_q || dbus_rsp_valid_i;
  assign w_fault  = w_valid_q && w_mem_q && dbus_rsp_valid_i && dbus_rsp_err_i;
  assign rf_we    = w_valid_q && w_ready && !w_fault && w_rd_we_q;
  assign rf_wdata = w_load_q ? w_load_value : w_result_q;

  // ------------------------------------------------------------------------------------------
  // Register file
  logic        e_accept;
  logic [31:0] rf_rdata_a, rf_rdata_b;

  // While E holds its instruction the register file keeps reading E's own sources, so the read
  // data always reflects every write up to the previous edge and the bypass register only ever
  // has to cover the most recent one.
  htx_cpu_regfile u_regfile (
    .clk_i,
    .raddr_a_i (e_accept ? f_instr[19:15] : e_q.rs1),
    .raddr_b_i (e_accept ? f_instr[24:20] : e_q.rs2),
    .rdata_a_o (rf_rdata_a),
    .rdata_b_o (rf_rdata_b),
    .we_i      (rf_we),
    .waddr_i   (w_rd_q),
    .wdata_i   (rf_wdata)
  );

  // ------------------------------------------------------------------------------------------
  // Execute: operands
  logic [31:0] rs1_val, rs2_val;

  always_comb begin
    if (w_valid_q && w_rd_we_q && (w_rd_q == e_q.rs1)) begin
      rs1_val = w_result_q;
    end else if (lw_valid_q && (lw_rd_q == e_q.rs1)) begin
      rs1_val = lw_data_q;
    end else begin
      rs1_val = rf_rdata_a;
    end
    if (w_valid_q && w_rd_we_q && (w_rd_q == e_q.rs2)) begin
      rs2_val = w_result_q;
    end else if (lw_valid_q && (lw_rd_q == e_q.rs2)) begin
      rs2_val = lw_data_q;
    end else begin
      rs2_val = rf_rdata_b;
    end
  end

  logic load_use;
  assign load_use = w_valid_q && w_load_q && w_rd_we_q &&
                    ((e_q.rs1_used && (e_q.rs1 == w_rd_q)) || (e_q.rs2_used && (e_q.rs2 == w_rd_q)));

  // ------------------------------------------------------------------------------------------
  // Execute: ALU, branches, address
  logic [31:0] alu_a, alu_b, alu_result, alu_sum;
  logic        alu_eq, alu_lt, alu_ltu;

  always_comb begin
    unique case (e_q.op_a_sel)
      htx_cpu_pkg::OpAPc:   alu_a = e_pc_q;
      htx_cpu_pkg::OpAZero: alu_a = 32'b0;
      default:              alu_a = rs1_val;
    endcase
  end
  assign alu_b = e_q.op_b_imm ? e_q.imm : rs2_val;

  htx_cpu_alu u_alu (
    .op_i     (e_q.alu_op),
    .a_i      (alu_a),
    .b_i      (alu_b),
    .result_o (alu_result),
    .sum_o    (alu_sum),
    .eq_o     (alu_eq),
    .lt_o     (alu_lt),
    .ltu_o    (alu_ltu)
  );

  logic branch_cond;
  always_comb begin
    unique case (e_q.funct3)
      3'b000:  branch_cond = alu_eq;
      3'b001:  branch_cond = !alu_eq;
      3'b100:  branch_cond = alu_lt;
      3'b101:  branch_cond = !alu_lt;
      3'b110:  branch_cond = alu_ltu;
      default: branch_cond = !alu_ltu;
    endcase
  end

  logic        taken;
  logic [31:0] jump_target, link;
  assign taken       = e_q.jal || e_q.jalr || (e_q.branch && branch_cond);
  assign jump_target = e_q.jalr ? {alu_sum[31:1], 1'b0} : e_target_q;
  assign link        = e_pc_q + 32'd4;

  logic [3:0]  lsu_be;
  logic [31:0] lsu_wdata;
  logic        lsu_misaligned;

  htx_cpu_lsu u_lsu (
    .req_size_i       (e_q.funct3[1:0]),
    .req_offset_i     (alu_sum[1:0]),
    .req_data_i       (rs2_val),
    .req_be_o         (lsu_be),
    .req_wdata_o      (lsu_wdata),
    .req_misaligned_o (lsu_misaligned),
    .rsp_funct3_i     (w_funct3_q),
    .rsp_offset_i     (w_result_q[1:0]),
    .rsp_rdata_i      (dbus_rsp_rdata_i),
    .rsp_value_o      (w_load_value)
  );

  // ------------------------------------------------------------------------------------------
  // Execute: traps
  // e_trap_early depends only on registered state and the low address bits, so the stall logic
  // never waits for a full-width compare; a taken branch to a misaligned target is only known
  // from the branch condition and traps without affecting the hand-over timing.
  logic                    e_trap, e_trap_early;
  htx_cpu_pkg::exc_cause_e e_cause;
  logic [31:0]             e_tval;

  assign e_trap_early = e_ferr_q || e_q.illegal || e_q.ecall || e_q.ebreak ||
                        (e_q.jal && e_target_q[1]) || (e_q.jalr && alu_sum[1]) ||
                        ((e_q.load || e_q.store) && lsu_misaligned);

  always_comb begin
    e_trap  = 1'b1;
    e_cause = htx_cpu_pkg::ExcIllegal;
    e_tval  = 32'b0;
    if (e_ferr_q) begin
      e_cause = htx_cpu_pkg::ExcInstrAccess;
      e_tval  = e_pc_q;
    end else if (e_q.illegal) begin
      e_cause = htx_cpu_pkg::ExcIllegal;
      e_tval  = e_q.imm;
    end else if (e_q.ecall) begin
      e_cause = htx_cpu_pkg::ExcEcallM;
    end else if (e_q.ebreak) begin
      e_cause = htx_cpu_pkg::ExcBreakpoint;
    end else if (taken && jump_target[1]) begin
      e_cause = htx_cpu_pkg::ExcInstrMisaligned;
      e_tval  = jump_target;
    end else if ((e_q.load || e_q.store) && lsu_misaligned) begin
      e_cause = e_q.store ? htx_cpu_pkg::ExcStoreMisaligned : htx_cpu_pkg::ExcLoadMisaligned;
      e_tval  = alu_sum;
    end else begin
      e_trap = 1'b0;
    end
  end

  // ------------------------------------------------------------------------------------------
  // Execute: multiply, divide, CSR
  logic        e_can_go, e_mem, e_mul, e_div, e_wait, e_done, e_commit, e_take_trap, e_redirect;
  logic        mul_done, div_done, div_busy;
  // A trap's CSR updates are applied one cycle after it is taken (together with the registered
  // redirect); nothing can read those CSRs in between, because the instruction then in E is squashed.
  logic                    trap_q;
  htx_cpu_pkg::exc_cause_e trap_cause_q;
  logic [31:2]             trap_pc_q;
  logic [31:0]             trap_tval_q;
  logic [31:0] mul_result, div_result, csr_rdata;
  logic [31:2] mtvec, mepc;

  // E holds a live instruction unless it entered on the wrong path while a redirect was decided.
  logic redirect_q;
  logic [31:2] redirect_pc_q;
  logic e_live;
  assign e_live   = e_valid_q && !redirect_q;
  assign e_can_go = e_live && !load_use && w_ready && !w_fault;
  assign e_mem    = (e_q.load || e_q.store) && !e_trap_early;
  assign e_mul    = e_q.mul && !e_trap_early;
  assign e_div    = e_q.div && !e_trap_early;

  htx_cpu_mul u_mul (
    .clk_i,
    .rst_ni,
    .start_i  (e_can_go && e_mul && !mul_done),
    .op_i     (e_q.funct3[1:0]),
    .a_i      (rs1_val),
    .b_i      (rs2_val),
    .done_o   (mul_done),
    .result_o (mul_result)
  );

  htx_cpu_div u_div (
    .clk_i,
    .rst_ni,
    .start_i  (e_can_go && e_div && !div_busy),
    .kill_i   (w_fault),
    .op_i     (e_q.funct3[1:0]),
    .a_i      (rs1_val),
    .b_i      (rs2_val),
    .busy_o   (div_busy),
    .done_o   (div_done),
    .result_o (div_result)
  );

  assign e_wait      = (e_mem && !dbus_req_ready_i) || (e_mul && !mul_done) || (e_div && !div_done);
  assign e_done      = e_can_go && !e_wait;
  assign e_commit    = e_done && !e_trap;
  assign e_take_trap = e_done && e_trap;
  assign e_redirect  = e_done && (e_trap || e_q.mret || e_q.fencei || (taken != e_pred_q));

  htx_cpu_csr u_csr (
    .clk_i,
    .rst_ni,
    .sel_i      (e_q.csr_sel),
    .rdata_o    (csr_rdata),
    .we_i       (e_done && !e_trap_early && e_q.csr && e_q.csr_we),
    .op_i       (e_q.funct3[1:0]),
    .src_i      (e_q.funct3[2] ? {27'b0, e_q.rs1} : rs1_val),
    .retire_i   (e_commit),
    .unretire_i (w_fault),
    .trap_i     (trap_q),
    .cause_i    (trap_cause_q),
    .trap_pc_i  (trap_pc_q),
    .tval_i     (trap_tval_q),
    .mret_i     (e_done && !e_trap_early && e_q.mret),
    .mtvec_o    (mtvec),
    .mepc_o     (mepc)
  );

  logic [31:0] e_result;
  always_comb begin
    if (e_q.load || e_q.store) begin
      e_result = alu_sum;
    end else if (e_q.jal || e_q.jalr) begin
      e_result = link;
    end else if (e_q.csr) begin
      e_result = csr_rdata;
    end else if (e_q.mul) begin
      e_result = mul_result;
    end else if (e_q.div) begin
      e_result = div_result;
    end else begin
      e_result = alu_result;
    end
  end

  // Data bus request: held stable while not accepted, because nothing it depends on can change
  // until E moves on (W has drained, the forwarded operands stay put).
  assign dbus_req_valid_o = e_can_go && e_mem;
  assign dbus_req_addr_o  = alu_sum;
  assign dbus_req_we_o    = e_q.store;
  assign dbus_req_be_o    = lsu_be;
  assign dbus_req_wdata_o = lsu_wdata;

  // ------------------------------------------------------------------------------------------
  // Redirects and stage hand-over
  logic        d_redirect;
  logic [31:2] late_pc;
  assign e_accept   = !e_live || e_done || w_fault;
  assign d_advance  = e_accept && !redirect_q && !w_fault;
  assign d_redirect = d_advance && f_valid && d_predict;
  assign redirect   = redirect_q || d_redirect;
  assign redirect_pc = redirect_q ? redirect_pc_q : d_target[31:2];

  always_comb begin
    if (w_fault || e_take_trap) begin
      late_pc = mtvec;
    end else if (e_q.mret) begin
      late_pc = mepc;
    end else if (taken && !e_pred_q) begin
      late_pc = jump_target[31:2];
    end else begin
      late_pc = link[31:2];
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      redirect_q <= 1'b0;
    end else begin
      redirect_q <= w_fault || e_redirect;
      trap_q     <= w_fault || e_take_trap;
    end
  end

  always_ff @(posedge clk_i) begin
    redirect_pc_q <= late_pc;
    trap_cause_q  <= w_fault ? (w_store_q ? htx_cpu_pkg::ExcStoreAccess : htx_cpu_pkg::ExcLoadAccess)
                             : e_cause;
    trap_pc_q     <= w_fault ? w_pc_q : e_pc_q[31:2];
    trap_tval_q   <= w_fault ? w_result_q : e_tval;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      e_valid_q  <= 1'b0;
      w_valid_q  <= 1'b0;
      lw_valid_q <= 1'b0;
    end else begin
      if (e_accept) begin
        e_valid_q <= f_valid && d_advance;
      end
      if (w_ready) begin
        w_valid_q <= e_commit;
      end
      if (rf_we) begin
        lw_valid_q <= 1'b1;
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (e_accept) begin
      e_q        <= d_dec;
      e_pc_q     <= f_pc;
      e_target_q <= d_target;
      e_pred_q   <= d_predict;
      e_ferr_q   <= f_err;
    end
    if (w_ready) begin
      w_rd_q     <= e_q.rd;
      w_rd_we_q  <= e_q.rd_we;
      w_load_q   <= e_q.load;
      w_store_q  <= e_q.store;
      w_mem_q    <= e_q.load || e_q.store;
      w_funct3_q <= e_q.funct3;
      w_result_q <= e_result;
      w_pc_q     <= e_pc_q[31:2];
    end
    if (rf_we) begin
      lw_rd_q   <= w_rd_q;
      lw_data_q <= rf_wdata;
    end
  end

endmodule
