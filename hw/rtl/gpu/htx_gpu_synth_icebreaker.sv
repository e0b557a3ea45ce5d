// Synthesis harness of the `icebreaker` GPU (htx_gpu_synth_top): the top of the synth-report entry gpu_icebreaker_up5k.
module htx_gpu_synth_icebreaker (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic sdi_i,
  output logic sdo_o
);
  htx_gpu_synth_top #(.Full(1'b0)) u_top (.*);
endmodule
