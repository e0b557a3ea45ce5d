// Shared definitions of the raster unit's texture port (docs/raster.md, "Texture port"): the
// width of the tag a fragment carries through the texture unit, so the GPU top and the raster
// agree on it, and the layout of that tag.
package htx_raster_pkg;
  // Tag = {depth_write, depth_func[2:0], modulate, textured, rgb[23:0], z[ZBits-1:0], addr[AddrW-1:0]}.
  localparam int unsigned TagFlagBits = 6;
  localparam int unsigned TagRgbBits  = 24;

  function automatic int unsigned tex_tag_w(input int unsigned addr_w, input int unsigned z_bits);
    tex_tag_w = addr_w + z_bits + TagRgbBits + TagFlagBits;
  endfunction

  // Perspective methods (the state word's METHOD field, htx::Method).
  localparam logic [2:0] MethodAffine  = 3'd0;
  localparam logic [2:0] MethodSubdiv  = 3'd1;
  localparam logic [2:0] MethodRecipLut = 3'd2;
  localparam logic [2:0] MethodRecipNr = 3'd3;
  localparam logic [2:0] MethodDivFree = 3'd4;
  // The methods the board's GPU builds (htx::icebreaker_board_methods(): AFFINE and RECIP_LUT), in
  // the synthesis report's gpu_icebreaker_up5k and soc_up5k. (A function: a package localparam
  // would be an unused parameter to Verilator in every other top.)
  function automatic logic [4:0] board_methods();
    board_methods = (5'd1 << MethodAffine) | (5'd1 << MethodRecipLut);
  endfunction
endpackage
