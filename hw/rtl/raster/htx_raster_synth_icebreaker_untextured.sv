// Synthesis and place-and-route harness of the raster unit in the `icebreaker` configuration
// without texture mapping (htx_raster_synth_wrapper with Methods = 0: flat and Gouraud colour,
// 16-bit depth; textured triangles are refused), no event counters; the synth-report design
// raster_icebreaker_untextured_up5k, the nearest raster build that places on the UP5K alone.
module htx_raster_synth_icebreaker_untextured (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic din_i,
  output logic dout_o
);
  htx_raster_synth_wrapper #(.Full(1'b0), .Methods(5'b00000), .Counters(1'b0))
  u_wrapper (
    .clk_i, .rst_ni, .din_i, .dout_o
  );
endmodule
