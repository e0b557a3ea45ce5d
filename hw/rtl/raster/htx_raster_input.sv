// Input stage: pops FIFO words and assembles one triangle (the state word, then the 30 words of
// vertex_record.h pack_triangle) while setup works on the previous one. Only the fields this
// slice uses are kept (state; per vertex x, y, z, rgba); the texel offsets, q_exp, q, uq and vq
// words are consumed and dropped until the texture slice adds their planes.
module htx_raster_input #(
  parameter int unsigned XW    = 24,
  parameter int unsigned ZBits = 24
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  input  logic               abort_i,
  input  logic               enable_i,

  input  logic               fifo_empty_i,
  output logic               fifo_pop_o,
  input  logic [31:0]        fifo_rdata_i,

  output logic               rec_valid_o,
  input  logic               rec_ready_i,
  output logic [31:0]        rec_state_o,
  output logic [3*XW-1:0]    rec_x_o,
  output logic [3*XW-1:0]    rec_y_o,
  output logic [3*ZBits-1:0] rec_z_o,
  output logic [3*32-1:0]    rec_rgba_o,

  output logic               busy_o,     // a triangle is partly or wholly taken from the FIFO
  output logic               partial_o   // some words of a triangle are in, the next is missing
);
  localparam int unsigned Words = 31;  // the state word and vertex_record.h kTriangleWords (30)

  logic [5:0]  req_q, got_q;
  logic        pending_q;
  logic [31:0] state_q;
  logic [31:0] x_q [3];
  logic [31:0] y_q [3];
  logic [31:0] z_q [3];
  logic [31:0] rgba_q [3];

  assign rec_valid_o = (got_q == 6'(Words));
  assign fifo_pop_o  = enable_i && !fifo_empty_i && (req_q != 6'(Words)) && !abort_i;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      req_q     <= '0;
      got_q     <= '0;
      pending_q <= 1'b0;
      state_q   <= '0;
      for (int i = 0; i < 3; i++) begin
        x_q[i] <= '0; y_q[i] <= '0; z_q[i] <= '0; rgba_q[i] <= '0;
      end
    end else if (abort_i) begin
      req_q     <= '0;
      got_q     <= '0;
      pending_q <= 1'b0;
    end else begin
      pending_q <= fifo_pop_o;
      if (fifo_pop_o) req_q <= req_q + 1'b1;
      if (pending_q) begin
        got_q <= got_q + 1'b1;
        // Word 0: state; 1..3: u_offset, v_offset, q_exp; then 9 words per vertex.
        if (got_q == 6'd0) state_q <= fifo_rdata_i;
        for (int i = 0; i < 3; i++) begin
          if (got_q == 6'(4 + 9 * i))     x_q[i]    <= fifo_rdata_i;
          if (got_q == 6'(4 + 9 * i + 1)) y_q[i]    <= fifo_rdata_i;
          if (got_q == 6'(4 + 9 * i + 2)) z_q[i]    <= fifo_rdata_i;
          if (got_q == 6'(4 + 9 * i + 8)) rgba_q[i] <= fifo_rdata_i;
        end
      end
      if (rec_valid_o && rec_ready_i) begin
        req_q <= '0;
        got_q <= '0;
      end
    end
  end

  for (genvar i = 0; i < 3; i++) begin : g_out
    assign rec_x_o[XW*i +: XW]       = x_q[i][XW-1:0];
    assign rec_y_o[XW*i +: XW]       = y_q[i][XW-1:0];
    assign rec_z_o[ZBits*i +: ZBits] = z_q[i][ZBits-1:0];
    assign rec_rgba_o[32*i +: 32]    = rgba_q[i];
  end
  assign rec_state_o = state_q;
  assign busy_o      = (req_q != '0);
  assign partial_o   = (got_q != '0) && (got_q != 6'(Words)) && fifo_empty_i && !pending_q;

  logic unused;
  assign unused = ^{x_q[0][31:XW], x_q[1][31:XW], x_q[2][31:XW], y_q[0][31:XW], y_q[1][31:XW],
                    y_q[2][31:XW], z_q[0], z_q[1], z_q[2]};
endmodule
