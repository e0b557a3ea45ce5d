// Formal harness (Yosys `sat`, two cycles): the core's decode, the decoder's record registered
// beside the decode table's entry as D does it, against the reference decoder
// (htx_cpu_decoder_ref, which takes the immediate and the CSR decode from the decoder's record)
// for every 32-bit instruction word. Proved: the same words are illegal;
// for a legal word every field execute and D's logic read is the same, except the ALU operation of
// a MUL- or DIV-class instruction and the write flag of anything but a CSR instruction, which
// nothing reads.
module htx_cpu_decode_formal (
  input logic        clk_i,
  input logic [31:0] instr_i
);
  htx_cpu_pkg::fetch_dec_t fdec, fdec_q;
  htx_cpu_pkg::decoded_t   dec, ref_dec, ref_q;

  htx_cpu_decoder u_decoder (
    .instr_i,
    .dec_o (fdec)
  );
  htx_cpu_decode_table u_table (
    .clk_i,
    .take_i  (1'b1),
    .instr_i,
    .fdec_i  (fdec_q),
    .dec_o   (dec)
  );
  htx_cpu_decoder_ref u_ref (
    .instr_i,
    .fdec_i (fdec),
    .dec_o  (ref_dec)
  );

  always_ff @(posedge clk_i) begin
    fdec_q <= fdec;
    ref_q  <= ref_dec;
  end

  logic past_valid_q = 1'b0;
  always_ff @(posedge clk_i) begin
    past_valid_q <= 1'b1;
  end

  always_comb begin
    if (past_valid_q) begin
      assert (dec.illegal == ref_q.illegal);
      assert (dec.mul == ref_q.mul);
      assert (dec.div == ref_q.div);
      if (!ref_q.illegal) begin
        assert (dec.ecall == ref_q.ecall);
        assert (dec.ebreak == ref_q.ebreak);
        assert (dec.mret == ref_q.mret);
        assert (dec.fencei == ref_q.fencei);
        assert (dec.branch == ref_q.branch);
        assert (dec.jal == ref_q.jal);
        assert (dec.jalr == ref_q.jalr);
        assert (dec.load == ref_q.load);
        assert (dec.store == ref_q.store);
        assert (dec.csr == ref_q.csr);
        assert (!dec.csr || (dec.csr_we == ref_q.csr_we));  // read only by a CSR instruction
        assert (dec.csr_sel == ref_q.csr_sel);
        assert (dec.funct3 == ref_q.funct3);
        assert (dec.rs1 == ref_q.rs1);
        assert (dec.rd == ref_q.rd);
        assert (dec.rd_we == ref_q.rd_we);
        assert (dec.mul || dec.div || (dec.alu_op == ref_q.alu_op));
        assert (dec.sub == ref_q.sub);
        assert (dec.signed_cmp == ref_q.signed_cmp);
        assert (dec.auipc == ref_q.auipc);
        assert (dec.a_zero == ref_q.a_zero);
        assert (dec.b_rs2 == ref_q.b_rs2);
        assert (dec.rs1_used == ref_q.rs1_used);
        assert (dec.rs2_used == ref_q.rs2_used);
        assert (dec.slt == ref_q.slt);
        assert (dec.shift == ref_q.shift);
        assert (dec.left == ref_q.left);
        assert (dec.arith == ref_q.arith);
        assert (dec.imm == ref_q.imm);
      end
    end
  end

endmodule
