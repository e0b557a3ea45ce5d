// Reference decoder for the decode equivalence proof (htx_cpu_decode_formal): the core's decoder
// as it was before the decode table (2026-12-07), one case statement over the whole instruction,
// with the operand controls htx_cpu then decoded beside it. It is not part of the core.
module htx_cpu_decoder_ref (
  input  logic [31:0]               instr_i,
  output htx_cpu_pkg::decoded_t     dec_o
);

  localparam logic [6:0] OpcLoad    = 7'b0000011;
  localparam logic [6:0] OpcMiscMem = 7'b0001111;
  localparam logic [6:0] OpcOpImm   = 7'b0010011;
  localparam logic [6:0] OpcAuipc   = 7'b0010111;
  localparam logic [6:0] OpcStore   = 7'b0100011;
  localparam logic [6:0] OpcOp      = 7'b0110011;
  localparam logic [6:0] OpcLui     = 7'b0110111;
  localparam logic [6:0] OpcBranch  = 7'b1100011;
  localparam logic [6:0] OpcJalr    = 7'b1100111;
  localparam logic [6:0] OpcJal     = 7'b1101111;
  localparam logic [6:0] OpcSystem  = 7'b1110011;

  logic [6:0]  opcode;
  logic [2:0]  funct3;
  logic [6:0]  funct7;
  logic [11:0] csr_addr;
  logic [31:0] imm_i, imm_s, imm_u, imm_b, imm_j;

  assign opcode   = instr_i[6:0];
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

  htx_cpu_pkg::decoded_t d;
  logic legal;

  always_comb begin
    d          = '0;
    d.funct3   = funct3;
    d.rs1      = instr_i[19:15];
    d.rd       = instr_i[11:7];
    d.alu_op   = htx_cpu_pkg::AluAdd;
    d.csr_sel  = csr_sel;
    d.imm      = imm;
    legal      = 1'b0;
    if (instr_i[1:0] == 2'b11) begin
      unique case (opcode)
        OpcLui: begin
          legal      = 1'b1;
          d.rd_we    = 1'b1;
        end
        OpcAuipc: begin
          legal      = 1'b1;
          d.rd_we    = 1'b1;
        end
        OpcJal: begin
          legal   = 1'b1;
          d.jal   = 1'b1;
          d.rd_we = 1'b1;
        end
        OpcJalr: begin
          legal      = (funct3 == 3'b000);
          d.jalr     = 1'b1;
          d.rd_we    = 1'b1;
        end
        OpcBranch: begin
          legal      = (funct3 != 3'b010) && (funct3 != 3'b011);
          d.branch   = 1'b1;
          d.alu_op   = htx_cpu_pkg::AluSub;
        end
        OpcLoad: begin
          legal      = (funct3 != 3'b011) && (funct3 != 3'b110) && (funct3 != 3'b111);
          d.load     = 1'b1;
          d.rd_we    = 1'b1;
        end
        OpcStore: begin
          legal      = (funct3 == 3'b000) || (funct3 == 3'b001) || (funct3 == 3'b010);
          d.store    = 1'b1;
        end
        OpcOpImm: begin
          d.rd_we    = 1'b1;
          legal      = 1'b1;
          unique case (funct3)
            3'b000: d.alu_op = htx_cpu_pkg::AluAdd;
            3'b010: d.alu_op = htx_cpu_pkg::AluSlt;
            3'b011: d.alu_op = htx_cpu_pkg::AluSltu;
            3'b100: d.alu_op = htx_cpu_pkg::AluXor;
            3'b110: d.alu_op = htx_cpu_pkg::AluOr;
            3'b111: d.alu_op = htx_cpu_pkg::AluAnd;
            3'b001: begin
              d.alu_op = htx_cpu_pkg::AluSll;
              legal    = (funct7 == 7'b0000000);
            end
            default: begin  // 3'b101
              d.alu_op = funct7[5] ? htx_cpu_pkg::AluSra : htx_cpu_pkg::AluSrl;
              legal    = (funct7 == 7'b0000000) || (funct7 == 7'b0100000);
            end
          endcase
        end
        OpcOp: begin
          d.rd_we    = 1'b1;
          if (funct7 == 7'b0000001) begin
            legal = 1'b1;
            d.mul = ~funct3[2];
            d.div = funct3[2];
          end else begin
            unique case (funct3)
              3'b000: d.alu_op = funct7[5] ? htx_cpu_pkg::AluSub : htx_cpu_pkg::AluAdd;
              3'b001: d.alu_op = htx_cpu_pkg::AluSll;
              3'b010: d.alu_op = htx_cpu_pkg::AluSlt;
              3'b011: d.alu_op = htx_cpu_pkg::AluSltu;
              3'b100: d.alu_op = htx_cpu_pkg::AluXor;
              3'b101: d.alu_op = funct7[5] ? htx_cpu_pkg::AluSra : htx_cpu_pkg::AluSrl;
              3'b110: d.alu_op = htx_cpu_pkg::AluOr;
              default: d.alu_op = htx_cpu_pkg::AluAnd;
            endcase
            legal = (funct7 == 7'b0000000) ||
                    ((funct7 == 7'b0100000) && ((funct3 == 3'b000) || (funct3 == 3'b101)));
          end
        end
        OpcMiscMem: begin
          // FENCE orders nothing here (one in-order hart, no caches); FENCE.I refetches.
          legal    = (funct3 == 3'b000) || (funct3 == 3'b001);
          d.fencei = (funct3 == 3'b001);
        end
        OpcSystem: begin
          if (funct3 == 3'b000) begin
            // mtval of ECALL and EBREAK is 0: the adder computes 0 + 0 (their B-format imm is 0).
            unique case (instr_i[31:7])
              25'h0000000: begin legal = 1'b1; d.ecall  = 1'b1; end
              25'h0002000: begin legal = 1'b1; d.ebreak = 1'b1; end
              25'h0604000: begin legal = 1'b1; d.mret   = 1'b1; end
              25'h020a000: legal = 1'b1;  // WFI: a legal no-op
              default:     legal = 1'b0;
            endcase
          end else if (funct3 != 3'b100) begin
            d.csr      = 1'b1;
            d.rd_we    = 1'b1;
            d.csr_we   = (funct3[1:0] == 2'b01) || (instr_i[19:15] != 5'd0);
            legal      = csr_known && !(csr_read_only && d.csr_we);
          end
        end
        default: legal = 1'b0;
      endcase
    end
    if (d.rd == 5'd0) begin
      d.rd_we = 1'b0;
    end
    // Everything else stays as the opcode set it (docs/cpu.md): the early trap cancels the actions.
    if (!legal) begin
      d.illegal = 1'b1;
      d.mul     = 1'b0;
      d.div     = 1'b0;
    end
  end

  // The operand controls, as htx_cpu decoded them from the fetched word.
  always_comb begin
    dec_o            = d;
    dec_o.auipc      = (instr_i[6:2] == 5'b00101);
    dec_o.a_zero     = (instr_i[6:2] == 5'b01101) ||
                       ((instr_i[6:2] == 5'b01100) && instr_i[25] && instr_i[14]) ||
                       ((instr_i[6:2] == 5'b11100) && (instr_i[14] || (instr_i[13:12] == 2'b00)));
    dec_o.b_rs2      = (instr_i[6:2] == 5'b01100) || (instr_i[6:2] == 5'b11000);
    dec_o.sub        = (instr_i[6:2] == 5'b11000) ||
                       ((((instr_i[6:2] == 5'b01100) && !instr_i[25]) || (instr_i[6:2] == 5'b00100)) &&
                        (instr_i[14:13] == 2'b01)) ||
                       ((instr_i[6:2] == 5'b01100) && (instr_i[14:12] == 3'b000) && instr_i[30] &&
                        !instr_i[25]);
    dec_o.signed_cmp = ((instr_i[6:2] == 5'b11000) && !instr_i[13]) ||
                       (((instr_i[6:2] == 5'b01100) || (instr_i[6:2] == 5'b00100)) &&
                        (instr_i[14:12] == 3'b010));
    dec_o.rs1_used   = !instr_i[2] || (instr_i[6:2] == 5'b11001);
    dec_o.rs2_used   = (instr_i[6:2] == 5'b01100) || (instr_i[6:2] == 5'b01000) ||
                       (instr_i[6:2] == 5'b11000);
    dec_o.slt        = (d.alu_op == htx_cpu_pkg::AluSlt) || (d.alu_op == htx_cpu_pkg::AluSltu);
    dec_o.shift      = (d.alu_op == htx_cpu_pkg::AluSll) || (d.alu_op == htx_cpu_pkg::AluSrl) ||
                       (d.alu_op == htx_cpu_pkg::AluSra);
    dec_o.left       = (d.alu_op == htx_cpu_pkg::AluSll);
    dec_o.arith      = (d.alu_op == htx_cpu_pkg::AluSra);
  end

endmodule
