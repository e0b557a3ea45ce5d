// Reference decoder for the decode equivalence proof (htx_cpu_decode_formal): the core's decoder
// as it was before the decode table (2026-12-07), one case statement over the whole instruction,
// with the operand controls htx_cpu then decoded beside it. It is not part of the core. The parts
// the table did not change, the immediate and the CSR decode, are taken from the decoder's record
// of the same word (fdec_i) rather than written twice.
module htx_cpu_decoder_ref (
  input  logic [31:0]               instr_i,
  input  htx_cpu_pkg::fetch_dec_t   fdec_i,   // htx_cpu_decoder's record of instr_i
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

  assign opcode   = instr_i[6:0];
  assign funct3   = instr_i[14:12];
  assign funct7   = instr_i[31:25];

  htx_cpu_pkg::decoded_t d;
  logic legal;

  always_comb begin
    d          = '0;
    d.funct3   = funct3;
    d.rs1      = instr_i[19:15];
    d.rd       = instr_i[11:7];
    d.alu_op   = htx_cpu_pkg::AluAdd;
    d.csr_sel  = fdec_i.csr_sel;
    d.imm      = fdec_i.imm;
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
            legal      = fdec_i.csr_ok;  // the CSR exists and is not written if read-only
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
