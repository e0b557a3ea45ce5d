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

  // What decode hands to execute. funct3 is kept whole: it selects the branch condition, the memory
  // access size and sign, the multiply/divide operation and the CSR operation.
  typedef struct packed {
    logic        illegal;   // an early trap (mul, div clear; other flags as decoded); mtval 0
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
    logic        csr_we;    // the CSR instruction writes (csrrw*, or csrrs/c* with rs1/uimm != 0)
    csr_sel_e    csr_sel;
    logic [2:0]  funct3;
    logic [4:0]  rs1;       // also the CSRR*I immediate
    logic [4:0]  rd;
    logic        rd_we;     // writes a register other than x0
    alu_op_e     alu_op;
    logic [31:0] imm;       // in the instruction's format (SYSTEM: B, 0 for ECALL and EBREAK)
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
