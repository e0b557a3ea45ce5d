// One htx_raster_plane shared by every attribute plane of a triangle, in turn (the `icebreaker`
// configuration: one plane unit and its multiplier instead of nine). Every plane's vertex values
// arrive widened to VB signed bits (unsigned values zero-extended), so the unit computes each
// plane's exact n, g and start; the caller keeps each result at the plane's own width (its value
// modulo 2^AccW of that plane, as a plane unit of that width computes it).
//
// start_i starts planes 0 .. NFirst-1; late_start_i (any time after start_i) the rest, whose vertex
// values come later (AFFINE's u_i, v_i). Each result word goes out as the unit forms it (word_*_o,
// with res_idx_o); res_valid_o pulses as each plane finishes, with its full-precision gradients on
// gxw_o, gyw_o.
//
// Load = 1: values_i holds only the three values of the plane being worked on (its low 3 VB bits),
// which the caller loads (from block RAM) while want_o is high, for plane res_idx_o, and confirms
// with have_i; they must then stay until want_o rises again. No multiplexer over the planes.

module htx_raster_plane_seq #(
  parameter int unsigned NP     = 9,
  parameter int unsigned NFirst = 7,
  parameter int unsigned VB     = 38,   // widened vertex value bits (signed)
  parameter int unsigned DW     = 25,
  parameter int unsigned W      = 32,
  parameter int unsigned GF     = 24,
  parameter int unsigned ShiftW = 8,
  parameter int unsigned AccW   = VB + GF + 2,
  parameter int unsigned GW     = VB + DW + 2 + GF + 1,
  parameter int unsigned IdxW   = $clog2(NP),
  parameter bit          Load   = 1'b0,
  parameter bit          Jobs   = 1'b0,   // the unit's job_* port (htx_raster_plane)
  parameter bit          Ring   = 1'b0    // htx_raster_plane's Ring form (needs Load)
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,
  input  logic                  abort_i,
  input  logic                  start_i,
  input  logic                  late_start_i,
  input  logic [NP*3*VB-1:0]    values_i,      // plane p, vertex i at VB (3 p + i); Load: see above
  output logic                  want_o,
  input  logic                  have_i,
  input  logic signed [DW-1:0]  dx1_i, ndy1_i, ndx2_i, dy2_i,  // as htx_raster_plane's
  input  logic signed [DW-1:0]  dxs_i, dys_i,
  input  logic                  recip_valid_i,
  input  logic [W:0]            r_i,
  input  logic [ShiftW-1:0]     shift_i,
  input  logic                  det_neg_i,
  input  logic [2:0]            ring_pos_i,    // as htx_raster_plane's
  output logic [2:0]            ring_want_o,
  output logic                  val_turn_o,    // Ring: rotate the loaded values (htx_raster_plane)
  output logic                  res_valid_o,
  output logic [IdxW-1:0]       res_idx_o,
  output logic [GW-1:0]         gxw_o, gyw_o,
  output logic                  word_we_o,
  output logic [1:0]            word_sel_o,
  output logic [AccW:0]         word_o,       // as htx_raster_plane's
  output logic                  first_done_o,  // planes 0 .. NFirst-1 delivered (until start_i)
  output logic                  late_done_o,   // planes NFirst .. NP-1 delivered
  // Jobs: the unit's job port, for the caller while no plane is being worked on.
  input  logic                  job_i,
  input  logic signed [DW-1:0]  job_a_i,
  input  logic [2:0]            job_bsel_i,
  input  logic                  job_neg_i,
  input  logic                  job_acc_i,
  output logic                  job_done_o,
  output logic [2*DW+1:0]       job_sum_o
);
  logic [IdxW-1:0] idx_q;
  logic            run_q, kick_q, want_q, late_pend_q, first_done_q, late_done_q;
  logic            unit_done, finish, late_go;
  logic [VB-1:0]   a0, a1, a2;
  logic [AccW-1:0] unit_gx, unit_gy, unit_start;  // (the caller takes the words as they form)

  if (Load) begin : g_loaded
    assign {a2, a1, a0} = values_i[3*VB-1:0];
    logic unused_values;
    assign unused_values = ^values_i[NP*3*VB-1:3*VB];
  end else begin : g_indexed
    // An array indexed by the plane: a multiplexer per bit (a part-select at VB * 3 * idx_q would
    // be a shifter across all NP * 3 * VB bits).
    logic [3*VB-1:0] plane_values [NP];
    for (genvar p = 0; p < NP; p++) begin : g_values
      assign plane_values[p] = values_i[3*VB*p +: 3*VB];
    end
    assign {a2, a1, a0} = plane_values[idx_q];
  end
  // A plane starts (kick) at once, or with Load once its values are in (want_o, have_i).
  logic go_plane;
  assign go_plane = Load ? (want_q && have_i) : 1'b0;

  htx_raster_plane #(.VB(VB), .Signed(1'b1), .DW(DW), .W(W), .GF(GF), .Iterative(1'b1),
                     .Jobs(Jobs), .ShiftW(ShiftW), .AccW(AccW), .GW(GW), .Ring(Ring)) u_plane (
    .clk_i, .rst_ni,
    .abort_i,
    .start_i      (kick_q),
    .a0_i(a0), .a1_i(a1), .a2_i(a2),
    .dx1_i, .ndy1_i, .ndx2_i, .dy2_i,
    .dxs_i, .dys_i,
    .recip_valid_i,
    .r_i,
    .shift_i,
    .det_neg_i,
    .ring_pos_i,
    .ring_want_o,
    .val_turn_o,
    .done_o       (unit_done),
    .gx_o(unit_gx), .gy_o(unit_gy), .start_o(unit_start),
    .gxw_o, .gyw_o,
    .word_we_o, .word_sel_o, .word_o,
    .job_i, .job_a_i, .job_bsel_i, .job_neg_i, .job_acc_i, .job_done_o, .job_sum_o
  );

  // The unit's done_o is a level that stays up until it is started again; kick_q guards the one
  // clock in which a new start is issued while the previous plane's done is still showing.
  assign finish  = run_q && !kick_q && !want_q && unit_done;
  assign late_go = late_pend_q || late_start_i;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      idx_q        <= '0;
      run_q        <= 1'b0;
      kick_q       <= 1'b0;
      want_q       <= 1'b0;
      late_pend_q  <= 1'b0;
      first_done_q <= 1'b0;
      late_done_q  <= 1'b0;
    end else if (abort_i) begin
      run_q        <= 1'b0;
      kick_q       <= 1'b0;
      want_q       <= 1'b0;
      late_pend_q  <= 1'b0;
      first_done_q <= 1'b0;
      late_done_q  <= 1'b0;
    end else begin
      kick_q <= go_plane;
      if (go_plane) want_q <= 1'b0;
      if (late_start_i) late_pend_q <= 1'b1;
      if (start_i) begin
        idx_q        <= '0;
        run_q        <= 1'b1;
        kick_q       <= !Load;
        want_q       <= Load;
        late_pend_q  <= 1'b0;
        first_done_q <= 1'b0;
        late_done_q  <= 1'b0;
      end else if (finish) begin
        if (idx_q == IdxW'(NFirst - 1)) first_done_q <= 1'b1;
        if (idx_q == IdxW'(NP - 1)) begin
          late_done_q <= 1'b1;
          run_q       <= 1'b0;
        end else if ((idx_q == IdxW'(NFirst - 1)) && !late_go) begin
          run_q <= 1'b0;  // the late planes' values are not there yet
        end else begin
          if (idx_q == IdxW'(NFirst - 1)) late_pend_q <= 1'b0;
          idx_q  <= idx_q + 1'b1;
          kick_q <= !Load;
          want_q <= Load;
        end
      end else if (!run_q && first_done_q && !late_done_q && late_go) begin
        idx_q       <= IdxW'(NFirst);
        run_q       <= 1'b1;
        kick_q      <= !Load;
        want_q      <= Load;
        late_pend_q <= 1'b0;
      end
    end
  end

  logic unused_unit;
  assign unused_unit = ^{unit_gx, unit_gy, unit_start};
  assign want_o       = want_q;
  assign res_valid_o  = finish;
  assign res_idx_o    = idx_q;
  assign first_done_o = first_done_q;
  assign late_done_o  = late_done_q;
endmodule
