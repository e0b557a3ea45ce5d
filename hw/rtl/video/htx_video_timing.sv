// Horizontal and vertical counters of a video mode (VESA 640x480 at 60 Hz by default: 800 x 525
// clocks a frame). Line and column 0 are the first visible ones; blanking follows the visible
// part (front porch, sync, back porch), so a frame ends with the back porch of its last line.
module htx_video_timing #(
  parameter int unsigned HActive = 640,
  parameter int unsigned HFront  = 16,
  parameter int unsigned HSync   = 96,
  parameter int unsigned HBack   = 48,
  parameter int unsigned VActive = 480,
  parameter int unsigned VFront  = 10,
  parameter int unsigned VSync   = 2,
  parameter int unsigned VBack   = 33,
  parameter int unsigned HW      = 10,   // counter widths
  parameter int unsigned VW      = 10
) (
  input  logic          clk_i,
  input  logic          rst_ni,
  output logic [HW-1:0] h_o,
  output logic [VW-1:0] v_o,
  output logic          line_end_o,   // the last clock of a line
  output logic          frame_end_o,  // the last clock of a frame
  output logic          active_o,     // (h, v) is a visible pixel
  output logic          hsync_o,      // sync pulses, active high here (the output stage inverts)
  output logic          vsync_o
);
  localparam int unsigned HTotal = HActive + HFront + HSync + HBack;
  localparam int unsigned VTotal = VActive + VFront + VSync + VBack;

  logic [HW-1:0] h_q;
  logic [VW-1:0] v_q;
  assign line_end_o  = (h_q == HW'(HTotal - 1));
  assign frame_end_o = line_end_o && (v_q == VW'(VTotal - 1));

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      h_q <= '0;
      v_q <= '0;
    end else if (line_end_o) begin
      h_q <= '0;
      v_q <= frame_end_o ? '0 : v_q + VW'(1);
    end else begin
      h_q <= h_q + HW'(1);
    end
  end

  assign h_o      = h_q;
  assign v_o      = v_q;
  assign active_o = (h_q < HW'(HActive)) && (v_q < VW'(VActive));
  assign hsync_o  = (h_q >= HW'(HActive + HFront)) && (h_q < HW'(HActive + HFront + HSync));
  assign vsync_o  = (v_q >= VW'(VActive + VFront)) && (v_q < VW'(VActive + VFront + VSync));
endmodule
