// Behavioural model of the iCE40 UP5K's SB_SPRAM256KA (16 bits x 16K words, single port), written
// from Lattice's description of the cell, for the test of htx_fb_ram's SPRAM form only (Yosys
// knows the real cell): on a clock edge with CHIPSELECT, a write stores the nibbles MASKWREN
// enables, a read sets DATAOUT; DATAOUT holds otherwise. STANDBY, SLEEP and POWEROFF are only
// checked to be in their running state.
module SB_SPRAM256KA (
  input  logic [13:0] ADDRESS,
  input  logic [15:0] DATAIN,
  input  logic [3:0]  MASKWREN,
  input  logic        WREN,
  input  logic        CHIPSELECT,
  input  logic        CLOCK,
  input  logic        STANDBY,
  input  logic        SLEEP,
  input  logic        POWEROFF,
  output logic [15:0] DATAOUT
);
  logic [15:0] mem_q [16384];
  always_ff @(posedge CLOCK) begin
    if (STANDBY || SLEEP || !POWEROFF) $error("SB_SPRAM256KA: not in its running state");
    if (CHIPSELECT) begin
      if (WREN) begin
        for (int n = 0; n < 4; n++) begin
          if (MASKWREN[n]) mem_q[ADDRESS][4*n +: 4] <= DATAIN[4*n +: 4];
        end
      end else begin
        DATAOUT <= mem_q[ADDRESS];
      end
    end
  end
endmodule
