// Synthesis harness of the `full` GPU (htx_gpu_synth_top): the top of the synth-report entry gpu_full_up5k.
module htx_gpu_synth_full (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic sdi_i,
  output logic sdo_o
);
  htx_gpu_synth_top #(.Full(1'b1)) u_top (.*);
endmodule
