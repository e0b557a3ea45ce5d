// The framebuffer's RGB565 pixel format (docs/model.md §8): one colour channel quantised to its
// field. Shared by the fragment stage and the `icebreaker` serial combine stage, which quantises a
// channel a clock (htx_raster_fragment InRgb565, htx_tex_combine_serial Rgb565).
package htx_rgb565_pkg;
  // round(c (2^bits - 1) / 255) for a field of `bits` bits (5 or 6): x = c (2^bits - 1) + 128,
  // (x + (x >> 8)) >> 8. The product by the constant is written as (c << bits) - c, so it is an
  // adder and not a DSP.
  function automatic logic [7:0] quantise(input logic [7:0] c, input logic [2:0] bits);
    logic [15:0] x;
    x = (16'(c) << bits) - 16'(c) + 16'd128;
    quantise = 8'((x + (x >> 8)) >> 8);
  endfunction
endpackage
