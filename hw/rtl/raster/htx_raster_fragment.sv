// Fragment stage (docs/model.md §8): depth test against the stored depth (never, less, lequal,
// equal, greater, always), depth write when enabled, RGB565 colour write, and the fast clear.
// Two stages: F1 reads the stored depth (synchronous RAM), F2 compares and writes. A fragment in F2
// whose address equals the one written by the fragment just before it takes that written depth
// (the RAM returned the value from before the write). The stage never stalls; x, y come in clipped
// to the screen, and an address beyond the memory (stride x height too large) writes nothing.
// Forward = 0 (`icebreaker`, whose fragments come several clocks apart anyway): no such bypass;
// the stage takes no fragment in the clock after one it reads for, so every read comes after the
// last write (a stall of one clock, instead of an address comparison and a depth multiplexer).
// The clear fills pixels 0 .. height * stride - 1 one per clock and only starts while no fragment
// is in flight (the top holds setup meanwhile). It writes nothing and waits in a clock with
// clear_hold_i (the video scan-out reading the colour memory, which a clear would otherwise keep
// busy for whole picture lines; docs/video.md).
// InRgb565 = 1 (`icebreaker` with texture mapping): in_rgb_i[15:0] is the colour already quantised
// to RGB565 (the serial combine stage quantises a channel a clock on one quantiser,
// htx_tex_combine_serial); otherwise this stage quantises the three channels itself.
module htx_raster_fragment #(
  parameter int unsigned ZBits    = 24,
  parameter int unsigned AddrW    = 24,
  parameter int unsigned FbPixels = 76800,
  parameter bit          Forward  = 1'b1,
  parameter bit          InRgb565 = 1'b0
) (
  input  logic              clk_i,
  input  logic              rst_ni,
  input  logic              abort_i,

  input  logic              in_valid_i,
  output logic              in_ready_o,
  input  logic [AddrW-1:0]  in_addr_i,
  input  logic [ZBits-1:0]  in_z_i,
  input  logic [23:0]       in_rgb_i,    // r 7:0, g 15:8, b 23:16 (InRgb565: RGB565 in 15:0)
  input  logic [31:0]       in_state_i,

  input  logic              clear_start_i,
  input  logic              clear_color_i,
  input  logic              clear_depth_i,
  input  logic [15:0]       clear_rgb565_i,
  input  logic [23:0]       clear_z_i,
  input  logic [12:0]       height_i,
  input  logic [12:0]       stride_i,
  input  logic              clear_hold_i,
  output logic              clearing_o,

  // Memory ports (hw/rtl/fb/htx_fb.sv).
  output logic              zr_en_o,
  output logic [AddrW-1:0]  zr_addr_o,
  input  logic [ZBits-1:0]  zr_data_i,
  output logic              wc_en_o,
  output logic              wz_en_o,
  output logic [AddrW-1:0]  w_addr_o,
  output logic [15:0]       wc_data_o,
  output logic [ZBits-1:0]  wz_data_o,

  output logic              busy_o,
  output logic              pixel_o     // a fragment passed and wrote its colour
);
  localparam logic [ZBits-1:0] ZMax = {ZBits{1'b1}};

  // ---- F1: depth read ---------------------------------------------------------------------------
  logic             f2_valid_q, f2_zwrite_q;
  logic [AddrW-1:0] f2_addr_q;
  logic [ZBits-1:0] f2_z_q;
  logic [15:0]      f2_rgb565_q;
  logic [2:0]       f2_func_q;
  logic             in_range;
  logic [7:0]       q_r, q_g, q_b;

  assign q_r = htx_rgb565_pkg::quantise(in_rgb_i[7:0], 3'd5);
  assign q_g = htx_rgb565_pkg::quantise(in_rgb_i[15:8], 3'd6);
  assign q_b = htx_rgb565_pkg::quantise(in_rgb_i[23:16], 3'd5);

  assign in_range   = htx_cmp_pkg::below_const(32'(in_addr_i), 32'(AddrW'(FbPixels)));
  assign in_ready_o = !clearing_o && (Forward || !f2_valid_q);
  assign zr_en_o    = in_valid_i && in_ready_o && in_range;
  assign zr_addr_o  = in_addr_i;

  // ---- F2: test and write -----------------------------------------------------------------------
  logic             last_wz_valid_q;
  logic [AddrW-1:0] last_wz_addr_q;
  logic [ZBits-1:0] last_wz_q;
  logic [ZBits-1:0] stored;
  logic             pass;
  assign stored = (Forward && last_wz_valid_q && (last_wz_addr_q == f2_addr_q)) ? last_wz_q
                                                                               : zr_data_i;
  always_comb begin
    unique case (f2_func_q)
      3'd0: pass = 1'b0;
      3'd1: pass = f2_z_q <  stored;
      3'd2: pass = f2_z_q <= stored;
      3'd3: pass = f2_z_q == stored;
      3'd4: pass = f2_z_q >  stored;
      3'd5: pass = 1'b1;
      default: pass = 1'b0;
    endcase
  end

  // ---- Clear ------------------------------------------------------------------------------------
  // The clear walks pixels 0 .. height stride - 1 (and stops at the memory's end) row by row: the
  // row's end (the next row's first address) moves on by the stride at each row's last pixel, and
  // a count of the rows left says which row is the last. No height x stride product (a DSP), and
  // no column counter beside the address (2026-12-04: about 30 LUT4 fewer than counting columns
  // and rows against their maxima).
  logic             clr_q, clr_color_q, clr_depth_q, clr_last, clr_row_end;
  logic [AddrW-1:0] clr_addr_q;
  // A row's end is added to only while it is inside the memory (<= 2^AddrW), so EW bits hold it.
  localparam int unsigned EW = ((AddrW > 13) ? AddrW : 13) + 1;
  // clr_next_q is the address after clr_addr_q, a register of its own, so that the row's end is
  // compared with flip-flops and not behind the increment's carry chain.
  logic [EW-1:0]    clr_next_q, clr_end_q;
  logic [12:0]      clr_rows_q;           // rows left, the current one included
  assign clr_row_end = (clr_next_q == clr_end_q);
  assign clr_last    = (clr_row_end && (clr_rows_q == 13'd1)) ||
                       (clr_addr_q == AddrW'(FbPixels - 1));  // (it counts up from 0 by one)
  assign clearing_o = clr_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      f2_valid_q      <= 1'b0;
      f2_zwrite_q     <= 1'b0;
      f2_addr_q       <= '0;
      f2_z_q          <= '0;
      f2_rgb565_q     <= '0;
      f2_func_q       <= '0;
      last_wz_valid_q <= 1'b0;
      last_wz_addr_q  <= '0;
      last_wz_q       <= '0;
      clr_q           <= 1'b0;
      clr_color_q     <= 1'b0;
      clr_depth_q     <= 1'b0;
      clr_addr_q      <= '0;
      clr_next_q      <= '0;
      clr_end_q       <= '0;
      clr_rows_q      <= '0;
    end else if (abort_i) begin
      f2_valid_q      <= 1'b0;
      last_wz_valid_q <= 1'b0;
      clr_q           <= 1'b0;
    end else begin
      f2_valid_q <= zr_en_o;
      if (zr_en_o) begin
        f2_addr_q   <= in_addr_i;
        f2_z_q      <= in_z_i;
        f2_zwrite_q <= in_state_i[htx_raster_reg_pkg::RASTER_STATE_DEPTH_WRITE_LSB];
        f2_func_q   <= in_state_i[htx_raster_reg_pkg::RASTER_STATE_DEPTH_FUNC_LSB +: 3];
        f2_rgb565_q <= InRgb565 ? in_rgb_i[15:0] : {q_r[4:0], q_g[5:0], q_b[4:0]};
      end
      last_wz_valid_q <= wz_en_o;
      if (wz_en_o) begin
        last_wz_addr_q <= f2_addr_q;
        last_wz_q      <= f2_z_q;
      end
      if (clr_q) begin
        if (!clear_hold_i) begin
          clr_addr_q <= AddrW'(clr_next_q);
          clr_next_q <= clr_next_q + 1'b1;
          if (clr_row_end) begin
            clr_end_q  <= clr_end_q + EW'(stride_i);
            clr_rows_q <= clr_rows_q - 13'd1;
          end
          if (clr_last) clr_q <= 1'b0;
        end
      end else if (clear_start_i && (height_i != 13'd0) && (stride_i != 13'd0)) begin
        clr_q         <= 1'b1;
        clr_color_q   <= clear_color_i;
        clr_depth_q   <= clear_depth_i;
        clr_addr_q    <= '0;
        clr_next_q    <= EW'(1);
        clr_end_q     <= EW'(stride_i);
        clr_rows_q    <= height_i;
      end
    end
  end

  logic [ZBits-1:0] clear_z;
  assign clear_z = ((clear_z_i >> ZBits) != '0) ? ZMax : ZBits'(clear_z_i);

  assign wc_en_o   = clr_q ? (clr_color_q && !clear_hold_i) : (f2_valid_q && pass);
  assign wz_en_o   = clr_q ? (clr_depth_q && !clear_hold_i) : (f2_valid_q && pass && f2_zwrite_q);
  assign w_addr_o  = clr_q ? clr_addr_q : f2_addr_q;
  assign wc_data_o = clr_q ? clear_rgb565_i : f2_rgb565_q;
  assign wz_data_o = clr_q ? clear_z : f2_z_q;
  assign busy_o    = f2_valid_q || clr_q;
  assign pixel_o   = !clr_q && f2_valid_q && pass;

  logic unused;
  assign unused = ^{in_state_i, clear_z_i, q_r[7:5], q_g[7:6], q_b[7:5]};
endmodule
