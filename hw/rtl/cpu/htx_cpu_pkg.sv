// Shared types of the htx_cpu RV32IM core: ALU operations, operand selects, the decoded-instruction
// record that travels from decode into execute, CSR selectors and trap causes.
package htx_cpu_pkg;

  typedef enum logic [3:0] {
    AluAdd  = 4'd0,
    AluSub  = 4'd1,
    AluSll  = 4'd2,
    AluSlt  = 4'd3,
    AluSltu = 4'd4,
    AluXor  = 4'd5,
    AluSrl  = 4'd6,
    AluSra  = 4'd7,
    AluOr   = 4'd8,
    AluAnd  = 4'd9
  } alu_op_e;

  // CSRs the core implements. Anything else is an illegal instruction.
  typedef enum logic [3:0] {
    CsrMstatus  = 4'd0,
    CsrMisa     = 4'd1,
    CsrMie      = 4'd2,
    CsrMtvec    = 4'd3,
    CsrMscratch = 4'd4,
    CsrMepc     = 4'd5,
    CsrMcause   = 4'd6,
    CsrMtval    = 4'd7,
    CsrMip      = 4'd8,
    CsrCycle    = 4'd9,
    CsrCycleh   = 4'd10,
    CsrInstret  = 4'd11,
    CsrInstreth = 4'd12,
    CsrZero     = 4'd13  // the id registers, mconfigptr, mstatush, the mhpm counters: zero
  } csr_sel_e;

  // mcause exception codes (interrupt bit clear).
  typedef enum logic [3:0] {
    ExcInstrMisaligned = 4'd0,
    ExcInstrAccess     = 4'd1,
    ExcIllegal         = 4'd2,
    ExcBreakpoint      = 4'd3,
    ExcLoadMisaligned  = 4'd4,
    ExcLoadAccess      = 4'd5,
    ExcStoreMisaligned = 4'd6,
    ExcStoreAccess     = 4'd7,
    ExcEcallM          = 4'd11
  } exc_cause_e;

  // How an instruction's legality depends on more than its opcode and funct3 (the decode table's
  // entry says which; the decoder tests the other fields in fetch's cycle).
  typedef enum logic [2:0] {
    LegalNever   = 3'd0,
    LegalAlways  = 3'd1,
    LegalF7Zero  = 3'd2,  // funct7 is 0 (SLLI)
    LegalF7Shift = 3'd3,  // funct7 is 0 or 0x20 (SRLI, SRAI)
    LegalF7OpM   = 3'd4,  // funct7 is 0 or 1 (OP with funct3 other than 000 and 101)
    LegalF7OpAll = 3'd5,  // funct7 is 0, 0x20 or 1 (OP with funct3 000 or 101)
    LegalSystem  = 3'd6,  // exactly ECALL, EBREAK, MRET or WFI
    LegalCsr     = 3'd7   // an implemented CSR, and no write to a read-only one
  } legal_class_e;

  // One entry of the decode table (htx_cpu_decode_table), addressed by opcode[6:2] and funct3:
  // everything decode needs that depends on those eight bits only, with the few corrections that
  // funct7's bits 0 and 5 make left to the table's user.
  typedef struct packed {
    legal_class_e legal;
    logic        load;
    logic        store;
    logic        branch;
    logic        jal;
    logic        jalr;
    logic        csr;        // SYSTEM with funct3 other than 000 and 100
    logic        fencei;
    logic        auipc;
    logic        system;     // SYSTEM with funct3 000 (ECALL, EBREAK, MRET, WFI)
    logic        mul;        // OP with funct3[2] clear: a MUL-class instruction if funct7 is 1
    logic        div;        // OP with funct3[2] set: a DIV-class instruction if funct7 is 1
    logic        rd_we;      // writes rd (unless rd is x0)
    logic        sub;        // subtracts (SLT(I)(U), branches), unless a MUL-class instruction
    logic        sub30;      // subtracts if instr[30] (ADD/SUB)
    logic        signed_cmp; // SLT(I), BLT, BGE
    logic        b_rs2;      // operand b is rs2 (OP, BRANCH), else the immediate
    logic        a_zero;     // operand a is 0 (LUI; SYSTEM: mtval 0 + 0, CSRR*I)
    logic        rs1_used;   // may read rs1 (a superset is harmless: it can only add a stall)
    logic        rs2_used;
    alu_op_e     alu_op;
    logic        alu30;      // alu_op's bit 0 is set by instr[30] (SUB from ADD, SRA from SRL)
    logic        slt;        // SLT(I)(U), unless a MUL-class instruction
    logic        shift;      // SLL(I), SRL(I), SRA(I), unless MUL-class or DIV-class
    logic        left;       // SLL(I), unless MUL-class
    logic        arith30;    // SRA(I) if instr[30]
  } table_entry_t;
  localparam int TableEntryBits = 31;  // $bits(table_entry_t), for Yosys

  // What the decoder finds in fetch's cycle beside the table: the immediate, the CSR, the fields
  // funct7 and the SYSTEM encodings are checked against. D registers it as it takes the
  // instruction.
  typedef struct packed {
    logic [31:0] imm;       // in the instruction's format (SYSTEM: B, 0 for ECALL and EBREAK)
    csr_sel_e    csr_sel;
    logic        csr_we;    // a CSR instruction would write (csrrw*, or csrrs/c* with rs1/uimm != 0)
    logic        csr_ok;    // the CSR is implemented and not written if read-only
    logic        ecall;     // instr[31:7] is ECALL's (and so on; the table's `system` gates them)
    logic        ebreak;
    logic        mret;
    logic        system_ok; // one of ECALL, EBREAK, MRET, WFI
    logic        f7_zero;   // funct7 is 0
    logic        f7_20;     // funct7 is 0x20
    logic        f7_one;    // funct7 is 1
    logic        m_ok;      // funct7 is 1 and instr[1:0] is 11 (an M instruction if OP)
    logic        quad;      // instr[1:0] is 11 (a 32-bit instruction)
    logic        rd_nz;     // rd is not x0
    logic        i30;       // instr[30]
    logic [2:0]  funct3;
    logic [4:0]  rs1;       // also the CSRR*I immediate
    logic [4:0]  rd;
  } fetch_dec_t;

  // What decode hands to D's logic (htx_cpu_decode_table joins the table's entry and the
  // decoder's record). An illegal instruction has mul and div clear and jal clear; its other
  // flags are left as its opcode set them, since it traps before execute acts.
  typedef struct packed {
    logic        illegal;   // an early trap; mtval 0
    logic        ecall;
    logic        ebreak;
    logic        mret;
    logic        fencei;
    logic        branch;
    logic        jal;
    logic        jalr;
    logic        load;
    logic        store;
    logic        mul;
    logic        div;
    logic        csr;
    logic        csr_we;
    csr_sel_e    csr_sel;
    logic [2:0]  funct3;
    logic [4:0]  rs1;       // also the CSRR*I immediate
    logic [4:0]  rd;
    logic        rd_we;     // writes a register other than x0
    alu_op_e     alu_op;
    logic        sub;       // operand b inverted, carry in 1
    logic        signed_cmp;
    logic        auipc;
    logic        a_zero;
    logic        b_rs2;
    logic        rs1_used;
    logic        rs2_used;
    logic        slt;
    logic        shift;
    logic        left;
    logic        arith;
    logic [31:0] imm;
  } decoded_t;

  // The part of a decoded instruction that execute still needs (operands, traps and targets are
  // resolved in decode and travel separately).
  typedef struct packed {
    logic        mret;
    logic        fencei;
    logic        branch;
    logic        jal;
    logic        jalr;
    logic        load;
    logic        store;
    logic        mul;
    logic        csr;
    logic        csr_we;
    csr_sel_e    csr_sel;
    logic [2:0]  funct3;
    logic [4:0]  uimm;      // rs1 field: CSRR*I immediate
    logic [4:0]  rd;
    logic        rd_we;
    alu_op_e     alu_op;
  } exec_t;

  // A load's lane choices, decoded in E from funct3 and the address's low bits so that W's
  // extension of the bus word takes only one-hot selects from flip-flops (all zero for anything
  // but a load).
  typedef struct packed {
    logic [3:0] lane;     // bits 7:0 come from byte lane k
    logic [3:0] sign;     // the fill is bit 7 of byte lane k (signed byte or half-word loads)
    logic       mid_lo;   // bits 15:8 from lane 1 (half-word at offset 0, word)
    logic       mid_hi;   // bits 15:8 from lane 3 (half-word at offset 2)
    logic       mid_fill; // bits 15:8 are the fill (byte loads)
    logic       word;     // bits 31:16 from lanes 3:2 (else the fill)
  } load_sel_t;

endpackage
