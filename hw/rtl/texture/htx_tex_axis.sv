// One axis of the texel address (docs/model.md §7, docs/texture.md): the coordinate at a level,
// u_L = u >> L, then for nearest the texel (u_L - 1) >> TF (ties go to the lower texel), for
// bilinear p = (u_L - 2^(TF-1) + 2^(TF-9)) >> (TF-8) with i0 = p >> 8 and the weight p & 255; both
// indices wrapped into the level (repeat, clamp, mirror; 3 acts as repeat). Combinational.
module htx_tex_axis #(
  parameter int unsigned CoordW = 48,  // signed coordinate width, TF fraction bits
  parameter int unsigned TF     = 16   // >= 9
) (
  input  logic [CoordW-1:0] coord_i,
  input  logic [3:0]        level_i,       // 0..8
  input  logic [3:0]        log2_size_i,   // level 0: 3..8
  input  logic [1:0]        wrap_i,
  input  logic              nearest_i,
  output logic [7:0]        i0_o,          // wrapped texel index (nearest: the texel)
  output logic [7:0]        i1_o,          // wrapped i0 + 1 (nearest: equal to i0_o)
  output logic [7:0]        weight_o,      // weight of i1 (nearest: 0)
  output logic [3:0]        log2_level_o   // log2 of the level's size on this axis
);
  localparam int unsigned IW = CoordW - TF + 1;  // signed integer part of t

  logic signed [CoordW-1:0] coord_l;
  logic signed [CoordW:0]   t, bias;
  logic signed [IW-1:0]     i0;
  logic signed [IW:0]       i0x, i1x;
  logic [3:0]               lw;
  logic [8:0]               mask;

  assign coord_l = $signed(coord_i) >>> level_i;
  assign bias = nearest_i ? -(CoordW+1)'(1)
                          : -(CoordW+1)'(1 << (TF - 1)) + (CoordW+1)'(1 << (TF - 9));
  assign t    = {coord_l[CoordW-1], coord_l} + bias;
  assign i0   = t[CoordW:TF];
  assign i0x  = {i0[IW-1], i0};
  assign i1x  = i0x + (IW+1)'(1);
  assign lw   = (log2_size_i > level_i) ? log2_size_i - level_i : 4'd0;
  assign mask = (9'd1 << lw) - 9'd1;

  function automatic logic [7:0] wrap(input logic signed [IW:0] i, input logic [1:0] mode,
                                      input logic [3:0] lw_f, input logic [7:0] mask_f);
    logic neg, over, flip;
    neg  = i[IW];
    over = (|i[IW-1:8]) || (|(i[7:0] & ~mask_f));
    flip = |(i[8:0] & (9'd1 << lw_f));  // bit lw of i
    unique case (mode)
      2'd1:    wrap = neg ? 8'd0 : (over ? mask_f : i[7:0]);
      2'd2:    wrap = (flip ? ~i[7:0] : i[7:0]) & mask_f;
      default: wrap = i[7:0] & mask_f;
    endcase
  endfunction

  assign i0_o         = wrap(i0x, wrap_i, lw, mask[7:0]);
  assign i1_o         = nearest_i ? i0_o : wrap(i1x, wrap_i, lw, mask[7:0]);
  assign weight_o     = nearest_i ? 8'd0 : t[TF-1 -: 8];
  assign log2_level_o = lw;

  logic unused;
  assign unused = ^{t[TF-9:0], mask[8]};
endmodule
