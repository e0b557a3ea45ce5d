// SUBDIV_n (docs/model.md §5.3) after the divider: the divider gives exact coordinates at a span's
// first pixel, every n pixels after it and its last pixel; between exact points a and b (L = b - a
// <= 64 pixels) this stage interpolates
//   inv_L = round(2^16 / L) (64-entry table), step = round((u_b - u_a) inv_L 2^-8),
//   u(a + j) = u_a + round(j step 2^-8).
// A pixel between a and b needs b, which comes later, so every fragment waits in a FIFO (Depth >= 64
// entries: a segment's 63 inner pixels and b) and an inner pixel leaves once its b is in; exact
// points and fragments of other methods leave as soon as they reach the head. Order is kept.
module htx_raster_subdiv #(
  parameter int unsigned LocW  = 32,
  parameter int unsigned PayW  = 8,
  parameter int unsigned Depth = 128   // power of two, >= 64
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             abort_i,

  input  logic             in_valid_i,
  output logic             in_ready_o,
  input  logic             in_subdiv_i,   // the fragment's triangle uses SUBDIV
  input  logic             in_exact_i,    // an exact point (u, v divided); else u, v are ignored
  input  logic [12:0]      in_x_i,
  input  logic [LocW-1:0]  in_u_i, in_v_i, // SUBDIV: exact values; other methods: final values
  input  logic [PayW-1:0]  in_pay_i,

  output logic             out_valid_o,
  input  logic             out_ready_i,
  output logic [LocW-1:0]  out_u_o, out_v_o,
  output logic [PayW-1:0]  out_pay_o
);
  localparam int unsigned PW = $clog2(Depth);

  // round(2^16 / L) for L = 1..64 (index L - 1).
  logic [16:0] inv_rom [64];
  initial begin
    for (int unsigned l = 1; l <= 64; l++) inv_rom[l-1] = 17'(((1 << 17) + l) / (2 * l));
  end

  logic [PayW-1:0]  f_pay [Depth];
  logic [LocW-1:0]  f_u   [Depth];
  logic [LocW-1:0]  f_v   [Depth];
  logic [6:0]       f_x   [Depth];
  logic             f_sub [Depth];
  logic             f_ex  [Depth];
  logic [LocW-1:0]  e_u   [Depth];
  logic [LocW-1:0]  e_v   [Depth];
  logic [6:0]       e_x   [Depth];
  logic [PW:0]      wr_q, rd_q, ewr_q, erd_q;
  logic [LocW-1:0]  a_u_q, a_v_q;
  logic [6:0]       a_x_q;

  logic full, empty, e_empty, push, pop, h_sub, h_ex;
  logic [PW-1:0] rd, erd;
  assign rd      = rd_q[PW-1:0];
  assign erd     = erd_q[PW-1:0];
  assign full    = (wr_q[PW-1:0] == rd) && (wr_q[PW] != rd_q[PW]);
  assign empty   = (wr_q == rd_q);
  assign e_empty = (ewr_q == erd_q);
  assign in_ready_o = !full;
  assign push    = in_valid_i && !full;
  assign h_sub   = f_sub[rd];
  assign h_ex    = f_ex[rd];
  assign out_valid_o = !empty && (!h_sub || h_ex || !e_empty);
  assign pop     = out_valid_o && out_ready_i;

  // Inner pixel: interpolate between a (registers) and b (front of the exact queue).
  logic [6:0]  len, j;
  logic [16:0] inv;
  assign len = e_x[erd] - a_x_q;
  assign j   = f_x[rd] - a_x_q;
  assign inv = inv_rom[6'(len - 7'd1)];

  function automatic logic [LocW-1:0] lerp(input logic [LocW-1:0] ua, input logic [LocW-1:0] ub,
                                           input logic [16:0] inv_l, input logic [6:0] jj);
    logic signed [LocW+18:0] d, step;
    logic signed [LocW+26:0] t;
    d    = (LocW+19)'($signed(ub)) - (LocW+19)'($signed(ua));
    step = (d * $signed({2'b0, inv_l}) + $signed((LocW+19)'(128))) >>> 8;
    t    = (LocW+27)'(step) * $signed({1'b0, jj});
    lerp = ua + LocW'((t + $signed((LocW+27)'(128))) >>> 8);
  endfunction

  always_comb begin
    if (!h_sub || h_ex) begin
      out_u_o = f_u[rd];
      out_v_o = f_v[rd];
    end else begin
      out_u_o = lerp(a_u_q, e_u[erd], inv, j);
      out_v_o = lerp(a_v_q, e_v[erd], inv, j);
    end
  end
  assign out_pay_o = f_pay[rd];

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      wr_q <= '0; rd_q <= '0; ewr_q <= '0; erd_q <= '0;
      a_u_q <= '0; a_v_q <= '0; a_x_q <= '0;
    end else if (abort_i) begin
      wr_q <= '0; rd_q <= '0; ewr_q <= '0; erd_q <= '0;
    end else begin
      if (push) begin
        wr_q <= wr_q + 1'b1;
        if (in_subdiv_i && in_exact_i) ewr_q <= ewr_q + 1'b1;
      end
      if (pop) begin
        rd_q <= rd_q + 1'b1;
        if (h_sub && h_ex) begin
          erd_q <= erd_q + 1'b1;
          a_u_q <= f_u[rd];
          a_v_q <= f_v[rd];
          a_x_q <= f_x[rd];
        end
      end
    end
  end

  // Storage without reset (RAM-like).
  always_ff @(posedge clk_i) begin
    if (push) begin
      f_pay[wr_q[PW-1:0]] <= in_pay_i;
      f_u[wr_q[PW-1:0]]   <= in_u_i;
      f_v[wr_q[PW-1:0]]   <= in_v_i;
      f_x[wr_q[PW-1:0]]   <= in_x_i[6:0];
      f_sub[wr_q[PW-1:0]] <= in_subdiv_i;
      f_ex[wr_q[PW-1:0]]  <= in_exact_i;
      if (in_subdiv_i && in_exact_i) begin
        e_u[ewr_q[PW-1:0]] <= in_u_i;
        e_v[ewr_q[PW-1:0]] <= in_v_i;
        e_x[ewr_q[PW-1:0]] <= in_x_i[6:0];
      end
    end
  end

  logic unused;
  assign unused = ^in_x_i[12:7];
endmodule
