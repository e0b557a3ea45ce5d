// The state word check of the raster unit's input (htx_raster_setup's, and the plane-record
// reader's): a method this build leaves out, a subdivision length outside 2..64, DIVFREE's last
// mip level beyond 8 (its SUBDIV_N field, docs/raster.md), or a depth function beyond `always`.
// A build without any method (Methods = 0: no texture mapping) refuses a textured triangle
// instead, and takes an untextured one whatever its method field names. Combinational.
module htx_raster_state_check #(
  parameter logic [4:0] Methods = 5'b01111  // bit m: htx::Method m built
) (
  input  logic [31:0] state_i,
  output logic        bad_o
);
  logic [2:0] m;
  logic [6:0] n;
  assign m = state_i[htx_raster_reg_pkg::RASTER_STATE_METHOD_LSB +: 3];
  assign n = state_i[htx_raster_reg_pkg::RASTER_STATE_SUBDIV_N_LSB +: 7];
  assign bad_o = (m > 3'd4) ||
                 ((Methods != 5'd0) ? !Methods[m] : state_i[htx_raster_reg_pkg::RASTER_STATE_TEXTURED_LSB]) ||
                 ((m == htx_raster_pkg::MethodSubdiv) && ((n < 7'd2) || (n > 7'd64))) ||
                 ((m == htx_raster_pkg::MethodDivFree) && (n > 7'd8)) ||
                 (state_i[htx_raster_reg_pkg::RASTER_STATE_DEPTH_FUNC_LSB +: 3] > 3'd5);
endmodule
