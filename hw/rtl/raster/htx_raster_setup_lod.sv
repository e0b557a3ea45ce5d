// Setup's LOD gradients (docs/raster.md, "Setup"): the six full-precision gradients of uq, vq and q
// (x and y each) brought to GradW bits by one block shift for all six,
// s_g = max(0, msb(max |g|) + 2 - GradW), so that the texture unit's LOD keeps their ratios. Six
// magnitudes and six shifters side by side (synthesis removes them where nothing takes them).
module htx_raster_setup_lod #(
  parameter int unsigned GWU   = 90,    // a full-precision gradient's width (signed)
  parameter int unsigned GradW = 24     // lod_grad_bits
) (
  input  logic [6*GWU-1:0]   grad_i,    // uq x, uq y, vq x, vq y, q x, q y
  output logic [6*GradW-1:0] grad_o,    // each shifted right by shift_o
  output logic [7:0]         shift_o
);
  logic [GWU-1:0] lg [6];
  for (genvar i = 0; i < 6; i++) begin : g_in
    assign lg[i] = grad_i[GWU*i +: GWU];
  end

  logic [GWU-1:0] lg_or;    // OR of the six magnitudes: its msb is the largest one's
  logic [7:0]     lg_msb1;  // msb + 1 (0: all gradients zero)
  always_comb begin
    lg_msb1 = '0;
    for (int b = 0; b < GWU; b++) if (lg_or[b]) lg_msb1 = 8'(b + 1);
    shift_o = (lg_msb1 + 8'd1 > 8'(GradW)) ? lg_msb1 + 8'd1 - 8'(GradW) : 8'd0;
  end

  always_comb begin
    lg_or = '0;
    for (int i = 0; i < 6; i++) lg_or = lg_or | (lg[i][GWU-1] ? GWU'(-lg[i]) : lg[i]);
  end
  for (genvar i = 0; i < 6; i++) begin : g_lod
    logic [GWU-1:0] sh;
    assign sh = GWU'($signed(lg[i]) >>> shift_o);
    assign grad_o[GradW*i +: GradW] = sh[GradW-1:0];
    logic unused_sh;
    assign unused_sh = ^sh[GWU-1:GradW];
  end
endmodule
