// Signed AW-bit value times an unsigned 8-bit weight (a filter weight). ShiftAdd builds it from
// eight gated additions in logic, so Yosys does not spend an iCE40 DSP on it; otherwise `*`.
module htx_tex_mul #(
  parameter int unsigned AW       = 9,
  parameter bit          ShiftAdd = 1'b0
) (
  input  logic signed [AW-1:0] a_i,
  input  logic [7:0]           w_i,
  output logic signed [AW+8:0] p_o
);
  if (ShiftAdd) begin : g_shift_add
    always_comb begin
      p_o = '0;
      for (int k = 0; k < 8; k++) begin
        if (w_i[k]) p_o = p_o + ((AW+9)'(a_i) <<< k);
      end
    end
  end else begin : g_mul
    assign p_o = (AW+9)'(a_i) * $signed({1'b0, w_i});
  end
endmodule
