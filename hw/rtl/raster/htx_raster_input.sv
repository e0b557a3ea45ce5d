// Input stage: pops FIFO words and assembles one triangle (the state word, then the 30 words of
// vertex_record.h pack_triangle) while setup works on the previous one. q_exp is consumed and
// dropped: it cancels in u = uq / q (docs/model.md §1). uq and vq keep their low UQ bits (the
// encoder's q_bits + uv_int_bits).
module htx_raster_input #(
  parameter int unsigned XW    = 24,
  parameter int unsigned ZBits = 24,
  parameter int unsigned QBits = 32,
  parameter int unsigned UQ    = 48
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
  output logic [3*QBits-1:0] rec_q_o,
  output logic [3*UQ-1:0]    rec_uq_o,
  output logic [3*UQ-1:0]    rec_vq_o,
  output logic [31:0]        rec_u_off_o,
  output logic [31:0]        rec_v_off_o,

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
  logic [31:0] q_q [3];
  logic [63:0] uq_q [3];
  logic [63:0] vq_q [3];
  logic [31:0] u_off_q, v_off_q;

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
        q_q[i] <= '0; uq_q[i] <= '0; vq_q[i] <= '0;
      end
      u_off_q <= '0;
      v_off_q <= '0;
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
        if (got_q == 6'd1) u_off_q <= fifo_rdata_i;
        if (got_q == 6'd2) v_off_q <= fifo_rdata_i;
        for (int i = 0; i < 3; i++) begin
          if (got_q == 6'(4 + 9 * i))     x_q[i]        <= fifo_rdata_i;
          if (got_q == 6'(4 + 9 * i + 1)) y_q[i]        <= fifo_rdata_i;
          if (got_q == 6'(4 + 9 * i + 2)) z_q[i]        <= fifo_rdata_i;
          if (got_q == 6'(4 + 9 * i + 3)) q_q[i]        <= fifo_rdata_i;
          if (got_q == 6'(4 + 9 * i + 4)) uq_q[i][31:0]  <= fifo_rdata_i;
          if (got_q == 6'(4 + 9 * i + 5)) uq_q[i][63:32] <= fifo_rdata_i;
          if (got_q == 6'(4 + 9 * i + 6)) vq_q[i][31:0]  <= fifo_rdata_i;
          if (got_q == 6'(4 + 9 * i + 7)) vq_q[i][63:32] <= fifo_rdata_i;
          if (got_q == 6'(4 + 9 * i + 8)) rgba_q[i]     <= fifo_rdata_i;
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
    assign rec_q_o[QBits*i +: QBits] = q_q[i][QBits-1:0];
    assign rec_uq_o[UQ*i +: UQ]      = uq_q[i][UQ-1:0];
    assign rec_vq_o[UQ*i +: UQ]      = vq_q[i][UQ-1:0];
  end
  assign rec_u_off_o = u_off_q;
  assign rec_v_off_o = v_off_q;
  assign rec_state_o = state_q;
  assign busy_o      = (req_q != '0);
  assign partial_o   = (got_q != '0) && (got_q != 6'(Words)) && fifo_empty_i && !pending_q;

  logic unused;
  assign unused = ^{x_q[0][31:XW], x_q[1][31:XW], x_q[2][31:XW], y_q[0][31:XW], y_q[1][31:XW],
                    y_q[2][31:XW], z_q[0], z_q[1], z_q[2], q_q[0], q_q[1], q_q[2], uq_q[0], uq_q[1],
                    uq_q[2], vq_q[0], vq_q[1], vq_q[2]};
endmodule
