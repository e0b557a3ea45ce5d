// Decode's second half: a table in block RAM, addressed by opcode[6:2] and funct3 of the word D is
// taking, holds everything decode needs that depends on those eight bits only (the kind of
// instruction, its ALU operation and operand controls, and which fields its legality further
// depends on). It is read as D takes the instruction, like the register file, and holds its entry
// while D holds (the read enable), so the entry is D's register. The few bits of funct7 and the
// SYSTEM and CSR checks that complete it come from the decoder's record of the same word
// (htx_cpu_decoder, in fetch's cycle), which D registers beside it; this module joins the two
// into D's record. The table, 256 entries of 31 bits, is two SB_RAM40_4K; the core is about 45
// LUT4 smaller than with the same decode in logic (docs/cpu_area_log.md).
module htx_cpu_decode_table (
  input  logic                    clk_i,
  input  logic                    take_i,   // D takes fetch's instruction this cycle
  input  logic [31:0]             instr_i,  // fetch's instruction (opcode[6:2] and funct3 are used)
  input  htx_cpu_pkg::fetch_dec_t fdec_i,   // D's registered copy of the decoder's record
  output htx_cpu_pkg::decoded_t   dec_o
);

  // The entry of opcode[6:2] = op5 and funct3 = f3. Where a field does not matter (an illegal
  // encoding, a flag an instruction's kind never reads) it is whatever is simplest.
  function automatic logic [htx_cpu_pkg::TableEntryBits-1:0] entry(input logic [4:0] op5, input logic [2:0] f3);
    logic [2:0] legal;
    logic       load, store, branch, jal, jalr, csr, fencei, auipc, system, mul, div, rd_we, sub;
    logic       sub30, signed_cmp, b_rs2, a_zero, rs1_used, rs2_used, alu30, slt, shift, left, arith30;
    logic [3:0] alu_op;
    {load, store, branch, jal, jalr, csr, fencei, auipc, system, mul, div, rd_we, sub} = '0;
    {sub30, signed_cmp, b_rs2, a_zero, rs2_used, alu30, slt, shift, left, arith30} = '0;
    legal    = htx_cpu_pkg::LegalNever;
    alu_op   = htx_cpu_pkg::AluAdd;
    // Every instruction but LUI, AUIPC, JAL and MISC-MEM may read rs1 (opcode bit 2 clear, or JALR).
    rs1_used = !op5[0] || (op5 == 5'b11001);
    unique case (op5)
      5'b01101: begin  // LUI: 0 + immediate
        legal  = htx_cpu_pkg::LegalAlways;
        rd_we  = 1'b1;
        a_zero = 1'b1;
      end
      5'b00101: begin  // AUIPC: the result is fetch's target adder's PC + immediate
        legal = htx_cpu_pkg::LegalAlways;
        rd_we = 1'b1;
        auipc = 1'b1;
      end
      5'b11011: begin  // JAL
        legal = htx_cpu_pkg::LegalAlways;
        jal   = 1'b1;
        rd_we = 1'b1;
      end
      5'b11001: begin  // JALR
        legal = (f3 == 3'b000) ? htx_cpu_pkg::LegalAlways : htx_cpu_pkg::LegalNever;
        jalr  = 1'b1;
        rd_we = 1'b1;
      end
      5'b11000: begin  // BRANCH: a - b, eq or lt
        legal      = ((f3 == 3'b010) || (f3 == 3'b011)) ? htx_cpu_pkg::LegalNever : htx_cpu_pkg::LegalAlways;
        branch     = 1'b1;
        alu_op     = htx_cpu_pkg::AluSub;
        sub        = 1'b1;
        signed_cmp = !f3[1];
        b_rs2      = 1'b1;
        rs2_used   = 1'b1;
      end
      5'b00000: begin  // LOAD
        legal = ((f3 == 3'b011) || (f3 == 3'b110) || (f3 == 3'b111)) ? htx_cpu_pkg::LegalNever : htx_cpu_pkg::LegalAlways;
        load  = 1'b1;
        rd_we = 1'b1;
      end
      5'b01000: begin  // STORE
        legal    = (f3 <= 3'b010) ? htx_cpu_pkg::LegalAlways : htx_cpu_pkg::LegalNever;
        store    = 1'b1;
        rs2_used = 1'b1;
      end
      5'b00100, 5'b01100: begin  // OP-IMM, OP
        rd_we    = 1'b1;
        mul      = op5[3] && !f3[2];
        div      = op5[3] && f3[2];
        b_rs2    = op5[3];
        rs2_used = op5[3];
        legal    = op5[3] ? htx_cpu_pkg::LegalF7OpM : htx_cpu_pkg::LegalAlways;
        unique case (f3)
          3'b000: begin
            // ADD(I); SUB if instr[30] (OP only: in OP-IMM bit 30 is the immediate's)
            alu30 = op5[3];
            sub30 = op5[3];
            if (op5[3]) begin
              legal = htx_cpu_pkg::LegalF7OpAll;
            end
          end
          3'b010: begin
            alu_op     = htx_cpu_pkg::AluSlt;
            sub        = 1'b1;
            signed_cmp = 1'b1;
            slt        = 1'b1;
          end
          3'b011: begin
            alu_op = htx_cpu_pkg::AluSltu;
            sub    = 1'b1;
            slt    = 1'b1;
          end
          3'b100: alu_op = htx_cpu_pkg::AluXor;
          3'b110: alu_op = htx_cpu_pkg::AluOr;
          3'b111: alu_op = htx_cpu_pkg::AluAnd;
          3'b001: begin
            alu_op = htx_cpu_pkg::AluSll;
            shift  = 1'b1;
            left   = 1'b1;
            if (!op5[3]) begin
              legal = htx_cpu_pkg::LegalF7Zero;
            end
          end
          default: begin  // 3'b101: SRL(I); SRA(I) if instr[30]
            alu_op  = htx_cpu_pkg::AluSrl;
            alu30   = 1'b1;
            arith30 = 1'b1;
            shift   = 1'b1;
            legal   = op5[3] ? htx_cpu_pkg::LegalF7OpAll : htx_cpu_pkg::LegalF7Shift;
          end
        endcase
      end
      5'b00011: begin  // MISC-MEM: FENCE orders nothing here (one in-order hart); FENCE.I refetches
        legal  = (f3[2:1] == 2'b00) ? htx_cpu_pkg::LegalAlways : htx_cpu_pkg::LegalNever;
        fencei = (f3 == 3'b001);
      end
      5'b11100: begin  // SYSTEM
        // Operand a is 0 for ECALL and EBREAK (mtval 0 + 0) and for CSRR*I, whose source is then
        // e_a_q ORed with the immediate.
        a_zero = (f3 == 3'b000) || f3[2];
        if (f3 == 3'b000) begin
          legal  = htx_cpu_pkg::LegalSystem;
          system = 1'b1;
        end else if (f3 != 3'b100) begin
          legal = htx_cpu_pkg::LegalCsr;
          csr   = 1'b1;
          rd_we = 1'b1;
        end
      end
      default: ;
    endcase
    // (Yosys evaluates no struct members in a function: the fields in table_entry_t's order.)
    entry = {legal, load, store, branch, jal, jalr, csr, fencei, auipc, system, mul, div, rd_we, sub,
             sub30, signed_cmp, b_rs2, a_zero, rs1_used, rs2_used, alu_op, alu30, slt, shift, left, arith30};
  endfunction

  (* ram_style = "block" *) logic [htx_cpu_pkg::TableEntryBits-1:0] table_rom [256];
  initial begin
    for (int i = 0; i < 256; i++) begin
      table_rom[i] = entry(i[7:3], i[2:0]);
    end
  end

  htx_cpu_pkg::table_entry_t t_q;
  always_ff @(posedge clk_i) begin
    if (take_i) begin
      t_q <= table_rom[{instr_i[6:2], instr_i[14:12]}];
    end
  end

  // funct7 is 1 in an OP instruction: MUL-class or DIV-class, never illegal (the stall chain
  // starts the multiplier and divider before the early trap is known).
  logic mdiv, class_ok;
  assign mdiv = (t_q.mul || t_q.div) && fdec_i.m_ok;
  always_comb begin
    unique case (t_q.legal)
      htx_cpu_pkg::LegalNever:   class_ok = 1'b0;
      htx_cpu_pkg::LegalAlways:  class_ok = 1'b1;
      htx_cpu_pkg::LegalF7Zero:  class_ok = fdec_i.f7_zero;
      htx_cpu_pkg::LegalF7Shift: class_ok = fdec_i.f7_zero || fdec_i.f7_20;
      htx_cpu_pkg::LegalF7OpM:   class_ok = fdec_i.f7_zero || fdec_i.f7_one;
      htx_cpu_pkg::LegalF7OpAll: class_ok = fdec_i.f7_zero || fdec_i.f7_20 || fdec_i.f7_one;
      htx_cpu_pkg::LegalSystem:  class_ok = fdec_i.system_ok;
      default:      class_ok = fdec_i.csr_ok;  // LegalCsr
    endcase
  end

  always_comb begin
    dec_o            = '0;
    dec_o.illegal    = !(fdec_i.quad && class_ok);
    dec_o.ecall      = t_q.system && fdec_i.ecall;
    dec_o.ebreak     = t_q.system && fdec_i.ebreak;
    dec_o.mret       = t_q.system && fdec_i.mret;
    dec_o.fencei     = t_q.fencei;
    dec_o.branch     = t_q.branch;
    // (A JAL's target is its mtval when it traps, so an illegal word is never one.)
    dec_o.jal        = t_q.jal && fdec_i.quad;
    dec_o.jalr       = t_q.jalr;
    dec_o.load       = t_q.load;
    dec_o.store      = t_q.store;
    dec_o.mul        = t_q.mul && fdec_i.m_ok;
    dec_o.div        = t_q.div && fdec_i.m_ok;
    dec_o.csr        = t_q.csr;
    dec_o.csr_we     = fdec_i.csr_we;
    dec_o.csr_sel    = fdec_i.csr_sel;
    dec_o.funct3     = fdec_i.funct3;
    dec_o.rs1        = fdec_i.rs1;
    dec_o.rd         = fdec_i.rd;
    dec_o.rd_we      = t_q.rd_we && fdec_i.rd_nz;
    dec_o.alu_op     = t_q.alu_op;
    if (t_q.alu30 && fdec_i.i30) begin
      dec_o.alu_op = fdec_i.funct3[2] ? htx_cpu_pkg::AluSra : htx_cpu_pkg::AluSub;
    end
    dec_o.sub        = (t_q.sub && !mdiv) || (t_q.sub30 && fdec_i.i30);
    dec_o.signed_cmp = t_q.signed_cmp;
    dec_o.auipc      = t_q.auipc;
    // A divide's operand a is 0: E's adder then tests rs2 for zero (htx_cpu).
    dec_o.a_zero     = t_q.a_zero || (t_q.div && fdec_i.m_ok);
    dec_o.b_rs2      = t_q.b_rs2;
    dec_o.rs1_used   = t_q.rs1_used;
    dec_o.rs2_used   = t_q.rs2_used;
    dec_o.slt        = t_q.slt && !mdiv;
    dec_o.shift      = t_q.shift && !mdiv;
    dec_o.left       = t_q.left && !mdiv;
    dec_o.arith      = t_q.arith30 && fdec_i.i30;
    dec_o.imm        = fdec_i.imm;
  end

  logic unused_instr;
  assign unused_instr = ^{instr_i[31:15], instr_i[11:7], instr_i[1:0]};

endmodule
