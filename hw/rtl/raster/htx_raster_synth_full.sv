// Synthesis and place-and-route harness of the raster unit in the `full` configuration
// (htx_raster_synth_wrapper); the synth-report design raster_full_up5k.
module htx_raster_synth_full (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic din_i,
  output logic dout_o
);
  htx_raster_synth_wrapper #(.Full(1'b1)) u_wrapper (
    .clk_i, .rst_ni, .din_i, .dout_o
  );
endmodule
