// Setup's LOD gradients (docs/raster.md, "Setup"): the six full-precision gradients of uq, vq and q
// (x and y each) brought to GradW bits by one block shift for all six,
// s_g = max(0, msb(max |g|) + 2 - GradW), so that the texture unit's LOD keeps their ratios.
// Six magnitudes and six shifters side by side, or (Serial) one magnitude and one shift register
// taking the six in turn once the q, uq and vq planes are done. Without Lod nothing is built: the
// gradients read 0, the shift 0, and done_o stays high.
module htx_raster_setup_lod #(
  parameter int unsigned GWU    = 90,    // a full-precision gradient's width (signed)
  parameter int unsigned GradW  = 24,    // lod_grad_bits
  parameter bit          Lod    = 1'b1,
  parameter bit          Serial = 1'b0   // one gradient at a time (setup's shared plane unit)
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             abort_i,        // setup's planes are abandoned
  input  logic             start_i,        // a new triangle's planes start (Serial: back to idle)
  input  logic             planes_done_i,  // Serial: the q, uq and vq planes are done
  input  logic [6*GWU-1:0] grad_i,         // uq x, uq y, vq x, vq y, q x, q y
  output logic [6*GradW-1:0] grad_o,       // each shifted right by shift_o
  output logic [7:0]       shift_o,
  output logic             done_o          // grad_o and shift_o are this triangle's
);
  logic [GWU-1:0] lg [6];
  for (genvar i = 0; i < 6; i++) begin : g_in
    assign lg[i] = grad_i[GWU*i +: GWU];
  end

  logic [GWU-1:0] lg_or;    // OR of the six magnitudes: its msb is the largest one's
  logic [7:0]     lg_msb1;  // msb + 1 (0: all gradients zero)
  always_comb begin
    lg_msb1 = '0;
    for (int b = 0; b < GWU; b++) if (lg_or[b]) lg_msb1 = 8'(b + 1);
    shift_o = (lg_msb1 + 8'd1 > 8'(GradW)) ? lg_msb1 + 8'd1 - 8'(GradW) : 8'd0;
  end

  if (!Lod) begin : g_lod_off
    assign lg_or  = '0;
    assign done_o = 1'b1;
    assign grad_o = '0;
    logic unused_lod;
    assign unused_lod = ^{clk_i, rst_ni, grad_i, abort_i, start_i, planes_done_i};
  end else if (!Serial) begin : g_lod_par
    always_comb begin
      lg_or = '0;
      for (int i = 0; i < 6; i++) lg_or = lg_or | (lg[i][GWU-1] ? GWU'(-lg[i]) : lg[i]);
    end
    for (genvar i = 0; i < 6; i++) begin : g_lod
      logic [GWU-1:0] sh;
      assign sh = GWU'($signed(lg[i]) >>> shift_o);
      assign grad_o[GradW*i +: GradW] = sh[GradW-1:0];
      logic unused_sh;
      assign unused_sh = ^sh[GWU-1:GradW];
    end
    assign done_o = 1'b1;
    logic unused_seq;
    assign unused_seq = ^{clk_i, rst_ni, abort_i, start_i, planes_done_i};
  end else begin : g_lod_seq
    // OR the six magnitudes (6 clocks), then shift each one right in a register, 8 bits a clock
    // while 8 or more remain and then 1 (at most 7 + 7 clocks each), instead of a barrel shifter.
    typedef enum logic [2:0] {LsIdle, LsOr, LsLoad, LsShift, LsDone} ls_e;
    ls_e            ls_q;
    logic [2:0]     li_q;
    logic [7:0]     lcnt_q;
    logic [GWU-1:0] lor_q, lsel, lsr_q;
    logic [GradW-1:0] lgs_q [6];
    assign lsel = lg[li_q];
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        ls_q   <= LsIdle;
        li_q   <= '0;
        lcnt_q <= '0;
        lor_q  <= '0;
        lsr_q  <= '0;
        for (int i = 0; i < 6; i++) lgs_q[i] <= '0;
      end else if (abort_i || start_i) begin
        ls_q <= LsIdle;
      end else begin
        unique case (ls_q)
          LsIdle: if (planes_done_i) begin ls_q <= LsOr; li_q <= '0; lor_q <= '0; end
          LsOr: begin
            lor_q <= lor_q | (lsel[GWU-1] ? GWU'(-lsel) : lsel);
            li_q  <= (li_q == 3'd5) ? 3'd0 : li_q + 3'd1;
            if (li_q == 3'd5) ls_q <= LsLoad;
          end
          LsLoad: begin
            lsr_q  <= lsel;
            lcnt_q <= shift_o;
            ls_q   <= LsShift;
          end
          LsShift: begin
            if (lcnt_q >= 8'd8) begin
              lsr_q  <= GWU'($signed(lsr_q) >>> 8);
              lcnt_q <= lcnt_q - 8'd8;
            end else if (lcnt_q != 8'd0) begin
              lsr_q  <= GWU'($signed(lsr_q) >>> 1);
              lcnt_q <= lcnt_q - 8'd1;
            end else begin
              lgs_q[li_q] <= lsr_q[GradW-1:0];
              li_q        <= li_q + 3'd1;
              ls_q        <= (li_q == 3'd5) ? LsDone : LsLoad;
            end
          end
          default: ;
        endcase
      end
    end
    assign lg_or = lor_q;
    for (genvar i = 0; i < 6; i++) begin : g_lod
      assign grad_o[GradW*i +: GradW] = lgs_q[i];
    end
    assign done_o = (ls_q == LsDone);
  end
endmodule
