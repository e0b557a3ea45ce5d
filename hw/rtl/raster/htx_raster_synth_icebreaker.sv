// Synthesis and place-and-route harness of the raster unit in the `icebreaker` configuration
// (htx_raster_synth_wrapper) as the board's GPU builds it (gpu_icebreaker_up5k): AFFINE and
// RECIP_LUT, the texture request's LOD fields left out (the wrapper's !Full: the board's texture
// unit has no LOD unit), no event counters; the synth-report design raster_icebreaker_up5k.
module htx_raster_synth_icebreaker (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic din_i,
  output logic dout_o
);
  htx_raster_synth_wrapper #(.Full(1'b0), .Methods(htx_raster_pkg::board_methods()),
                            .Counters(1'b0)) u_wrapper (
    .clk_i, .rst_ni, .din_i, .dout_o
  );
endmodule
