// RV32IM + Zicsr instruction decoder, fetch's half (combinational): what depends on more of the
// instruction than opcode[6:2] and funct3, which the decode table in block RAM looks up as D takes
// the instruction (htx_cpu_decode_table, which joins the two into D's record). Here: the
// immediate (also for fetch's target adder), the CSR's selector and whether it exists, and the
// checks of funct7 and of the SYSTEM encodings that the table's legality classes refer to.
module htx_cpu_decoder (
  input  logic [31:0]               instr_i,
  output htx_cpu_pkg::fetch_dec_t   dec_o
);

  logic [2:0]  funct3;
  logic [6:0]  funct7;
  logic [11:0] csr_addr;
  logic [31:0] imm_i, imm_s, imm_u, imm_b, imm_j;

  assign funct3   = instr_i[14:12];
  assign funct7   = instr_i[31:25];
  assign csr_addr = instr_i[31:20];

  assign imm_i = {{20{instr_i[31]}}, instr_i[31:20]};
  assign imm_s = {{20{instr_i[31]}}, instr_i[31:25], instr_i[11:7]};
  assign imm_u = {instr_i[31:12], 12'b0};
  assign imm_b = {{20{instr_i[31]}}, instr_i[7], instr_i[30:25], instr_i[11:8], 1'b0};
  assign imm_j = {{12{instr_i[31]}}, instr_i[19:12], instr_i[20], instr_i[30:21], 1'b0};

  // The instruction's immediate in its format, for operand b and for fetch's target adder (JAL,
  // branches, AUIPC: htx_cpu adds it to the PC as D takes the instruction), one multiplexer for
  // both. The format comes from a few opcode bits (opcode[6:2]: U = LUI, AUIPC; J = JAL; B =
  // BRANCH and SYSTEM; S = STORE; I = the rest), right for every instruction that uses the
  // immediate and whatever is cheapest for the others (OP, MISC-MEM). SYSTEM takes the B format
  // because that is 0 for ECALL and EBREAK, whose mtval the adder forms as 0 + 0 (CSR
  // instructions, MRET and WFI do not use operand b).
  logic [31:0] imm;
  always_comb begin
    if (instr_i[2] && instr_i[4]) begin
      imm = imm_u;
    end else if (instr_i[3]) begin
      imm = imm_j;
    end else if (instr_i[6] && !instr_i[2]) begin
      imm = imm_b;
    end else if (instr_i[5] && !instr_i[6] && !instr_i[2]) begin
      imm = imm_s;
    end else begin
      imm = imm_i;
    end
  end

  // CSR address -> selector; read_only covers the user counter aliases and the machine id and
  // configuration registers. The zero CSRs (CsrZero) read 0.
  logic     csr_known;
  logic     csr_read_only;
  htx_cpu_pkg::csr_sel_e csr_sel;
  always_comb begin
    csr_known     = 1'b1;
    csr_read_only = 1'b0;
    csr_sel       = htx_cpu_pkg::CsrZero;
    unique case (csr_addr)
      12'h300: csr_sel = htx_cpu_pkg::CsrMstatus;
      12'h301: csr_sel = htx_cpu_pkg::CsrMisa;
      12'h304: csr_sel = htx_cpu_pkg::CsrMie;
      12'h305: csr_sel = htx_cpu_pkg::CsrMtvec;
      12'h340: csr_sel = htx_cpu_pkg::CsrMscratch;
      12'h341: csr_sel = htx_cpu_pkg::CsrMepc;
      12'h342: csr_sel = htx_cpu_pkg::CsrMcause;
      12'h343: csr_sel = htx_cpu_pkg::CsrMtval;
      12'h344: csr_sel = htx_cpu_pkg::CsrMip;
      12'hB00: csr_sel = htx_cpu_pkg::CsrCycle;
      12'hB02: csr_sel = htx_cpu_pkg::CsrInstret;
      12'hB80: csr_sel = htx_cpu_pkg::CsrCycleh;
      12'hB82: csr_sel = htx_cpu_pkg::CsrInstreth;
      12'hC00: begin csr_sel = htx_cpu_pkg::CsrCycle;    csr_read_only = 1'b1; end
      12'hC02: begin csr_sel = htx_cpu_pkg::CsrInstret;  csr_read_only = 1'b1; end
      12'hC80: begin csr_sel = htx_cpu_pkg::CsrCycleh;   csr_read_only = 1'b1; end
      12'hC82: begin csr_sel = htx_cpu_pkg::CsrInstreth; csr_read_only = 1'b1; end
      12'hF11, 12'hF12, 12'hF13, 12'hF14, 12'hF15: csr_read_only = 1'b1;
      12'h310: ;  // mstatush: little-endian only, zero, writes ignored
      // mhpmcounter3-31, their high halves and mhpmevent3-31: zero, writes ignored (the
      // privileged spec's legal minimum for the counters it says should exist).
      default: csr_known = ((csr_addr[11:5] == 7'h58) || (csr_addr[11:5] == 7'h5C) ||
                            (csr_addr[11:5] == 7'h19)) && (csr_addr[4:0] >= 5'd3);
    endcase
  end

  // The CSR instruction would write: CSRRW(I), or CSRRS(I)/CSRRC(I) with rs1/uimm not 0.
  logic csr_we;
  assign csr_we = (funct3[1:0] == 2'b01) || (instr_i[19:15] != 5'd0);

  always_comb begin
    dec_o           = '0;
    dec_o.imm       = imm;
    dec_o.csr_sel   = csr_sel;
    dec_o.csr_we    = csr_we;
    dec_o.csr_ok    = csr_known && !(csr_read_only && csr_we);
    // mtval of ECALL and EBREAK is 0: the adder computes 0 + 0 (their B-format imm is 0).
    dec_o.ecall     = (instr_i[31:7] == 25'h0000000);
    dec_o.ebreak    = (instr_i[31:7] == 25'h0002000);
    dec_o.mret      = (instr_i[31:7] == 25'h0604000);
    dec_o.system_ok = dec_o.ecall || dec_o.ebreak || dec_o.mret ||
                      (instr_i[31:7] == 25'h020a000);  // WFI: a legal no-op
    dec_o.f7_zero   = (funct7 == 7'b0000000);
    dec_o.f7_20     = (funct7 == 7'b0100000);
    dec_o.f7_one    = (funct7 == 7'b0000001);
    dec_o.quad      = (instr_i[1:0] == 2'b11);
    dec_o.m_ok      = dec_o.f7_one && dec_o.quad;
    dec_o.rd_nz     = (instr_i[11:7] != 5'd0);
    dec_o.i30       = instr_i[30];
    dec_o.funct3    = funct3;
    dec_o.rs1       = instr_i[19:15];
    dec_o.rd        = instr_i[11:7];
  end

endmodule
