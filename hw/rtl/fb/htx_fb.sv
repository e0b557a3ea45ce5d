// Framebuffer and depth buffer memories with their two users: the raster unit's fragment stage
// (depth read, colour and depth write; always served first) and a bus slave for the CPU windows
// (docs/contracts.md): colour at 0x3000_0000, RGB565, two pixels per 32-bit word (the lower address
// in bits 15:0); depth at 0x3010_0000, one pixel per word in the low ZBits. A bus access waits while
// the raster uses the port it needs. An address beyond the memory answers rsp_err (reads give 0).
// SinglePort = 1 (`icebreaker`, whose fragment stage never reads and writes depth in one clock): a
// bus access waits while the raster uses its memory at all, so each memory sees one access a clock
// and may be single-ported; Spram = 1 builds them from the UP5K's SPRAM (htx_fb_ram; ZBits = 16).
// A third user, the video scan-out (htx_video), reads colour words through vr_*: it waits only for
// the raster's colour writes (SinglePort) and goes before the bus, whose colour reads then wait.
// ColorPages = 2 or 3 (double or triple buffering, docs/video.md): the colour memory holds that many
// pages of FbPixels, page p from word p * FbPixels / 2 of the window; the raster's colour writes go
// to page c_page_i (its FB_PAGE.DRAW, always below ColorPages), the video and the bus address every
// page directly. Depth has one page.
module htx_fb #(
  parameter int unsigned ZBits      = 24,
  parameter int unsigned AddrW      = 24,
  parameter int unsigned FbPixels   = 76800,   // even
  parameter bit          SinglePort = 1'b0,
  parameter bit          Spram      = 1'b0,    // needs SinglePort and one colour page
  parameter int unsigned ColorPages = 1        // 1, 2 or 3
) (
  input  logic              clk_i,
  input  logic              rst_ni,

  input  logic              zr_en_i,
  input  logic [AddrW-1:0]  zr_addr_i,
  output logic [ZBits-1:0]  zr_data_o,
  input  logic              wc_en_i,
  input  logic              wz_en_i,
  input  logic [AddrW-1:0]  w_addr_i,
  input  logic [15:0]       wc_data_i,
  input  logic [1:0]        c_page_i,     // the page wc_* writes (below ColorPages)
  input  logic [ZBits-1:0]  wz_data_i,

  input  logic              vr_req_i,     // video: read colour word vr_addr_i (two pixels)
  input  logic [AddrW-1:0]  vr_addr_i,
  output logic              vr_gnt_o,     // read in this clock; the word is on vr_data_o next clock
  output logic [31:0]       vr_data_o,

  input  logic              req_valid_i,
  output logic              req_ready_o,
  input  logic [31:0]       req_addr_i,
  input  logic              req_we_i,
  input  logic [3:0]        req_be_i,
  input  logic [31:0]       req_wdata_i,
  output logic              rsp_valid_o,
  output logic [31:0]       rsp_rdata_o,
  output logic              rsp_err_o
);
  localparam int unsigned CWords = FbPixels / 2;                // a page
  localparam int unsigned CAW    = $clog2(CWords * ColorPages);  // every page
  localparam int unsigned ZAW    = $clog2(FbPixels);

  // ---- Bus decode ------------------------------------------------------------------------------
  logic        is_color, is_depth, in_range, accept, conflict;
  logic [17:0] bus_word;   // word index inside the 1 MiB window
  assign is_color = (req_addr_i[31:20] == 12'h300);
  assign is_depth = (req_addr_i[31:20] == 12'h301);
  assign bus_word = req_addr_i[19:2];
  assign in_range = is_color ? htx_cmp_pkg::below_const(32'(bus_word), CWords * ColorPages)
                             : (is_depth && htx_cmp_pkg::below_const(32'(bus_word), FbPixels));
  // The raster's ports come first: a bus read of depth needs the depth read port, a bus write the
  // write port of its memory (SinglePort: any access needs the memory's one port).
  // The video port's read needs the colour read port (SinglePort: the colour memory).
  if (SinglePort) begin : g_conflict_1p
    assign vr_gnt_o = vr_req_i && !wc_en_i;
    assign conflict = in_range && (is_color ? (wc_en_i || vr_req_i) : (zr_en_i || wz_en_i));
  end else begin : g_conflict_2p
    assign vr_gnt_o = vr_req_i;
    assign conflict = in_range && (req_we_i ? (is_color ? wc_en_i : wz_en_i)
                                            : (is_depth ? zr_en_i : vr_req_i));
  end
  assign req_ready_o = !conflict;
  assign accept = req_valid_i && req_ready_o;

  logic bus_rd_c, bus_rd_z, bus_wr_c, bus_wr_z;
  assign bus_rd_c = accept && in_range && !req_we_i && is_color;
  assign bus_rd_z = accept && in_range && !req_we_i && is_depth;
  assign bus_wr_c = accept && in_range && req_we_i && is_color;
  assign bus_wr_z = accept && in_range && req_we_i && is_depth && (&req_be_i);

  // ---- Colour: 32-bit words of two pixels --------------------------------------------------------
  logic [1:0]     c_we;
  logic [CAW-1:0] c_waddr, w_word;
  // The raster's word in its page (its addresses are below FbPixels: htx_raster_fragment).
  // Page p starts at p * CWords: page bit 0 adds CWords, bit 1 twice that (page 3 never comes).
  logic [CAW-1:0] page_base;
  assign page_base = ((ColorPages > 1 && c_page_i[0]) ? CAW'(CWords) : '0) +
                     ((ColorPages > 2 && c_page_i[1]) ? CAW'(2 * CWords) : '0);
  assign w_word = CAW'(w_addr_i >> 1) + page_base;
  logic [31:0]    c_wdata, c_rdata;
  always_comb begin
    if (wc_en_i) begin
      c_we    = w_addr_i[0] ? 2'b10 : 2'b01;
      c_waddr = w_word;
      c_wdata = {wc_data_i, wc_data_i};
    end else begin
      c_we    = bus_wr_c ? {&req_be_i[3:2], &req_be_i[1:0]} : 2'b00;
      c_waddr = (SinglePort && vr_gnt_o) ? CAW'(vr_addr_i) : CAW'(bus_word);
      c_wdata = req_wdata_i;
    end
  end
  // SinglePort: one address for both ports (the raster's write, else the video's read, else the
  // bus's), so the memory needs no read/write address multiplexer of its own.
  logic [CAW-1:0] c_raddr;
  assign c_raddr = SinglePort ? c_waddr : (vr_gnt_o ? CAW'(vr_addr_i) : CAW'(bus_word));
  htx_fb_ram #(.LaneW(16), .Lanes(2), .Words(CWords * ColorPages), .Spram(Spram)) u_color (
    .clk_i,
    .re_i   (bus_rd_c || vr_gnt_o),
    .raddr_i(c_raddr),
    .rdata_o(c_rdata),
    .we_i   (c_we),
    .waddr_i(c_waddr),
    .wdata_i(c_wdata)
  );

  // ---- Depth -------------------------------------------------------------------------------------
  logic           z_re, z_we;
  logic [ZAW-1:0] z_raddr, z_waddr;
  logic [ZBits-1:0] z_wdata, z_rdata;
  assign z_re    = zr_en_i || bus_rd_z;
  assign z_we    = wz_en_i || bus_wr_z;
  if (SinglePort) begin : g_zaddr_1p
    // One address: the raster's read or write (never both in a clock), else the bus's.
    assign z_raddr = zr_en_i ? ZAW'(zr_addr_i) : (wz_en_i ? ZAW'(w_addr_i) : ZAW'(bus_word));
    assign z_waddr = z_raddr;
  end else begin : g_zaddr_2p
    assign z_raddr = zr_en_i ? ZAW'(zr_addr_i) : ZAW'(bus_word);
    assign z_waddr = wz_en_i ? ZAW'(w_addr_i) : ZAW'(bus_word);
  end
  assign z_wdata = wz_en_i ? wz_data_i : ZBits'(req_wdata_i);
  htx_fb_ram #(.LaneW(ZBits), .Lanes(1), .Words(FbPixels), .Spram(Spram)) u_depth (
    .clk_i,
    .re_i   (z_re),
    .raddr_i(z_raddr),
    .rdata_o(z_rdata),
    .we_i   (z_we),
    .waddr_i(z_waddr),
    .wdata_i(z_wdata)
  );
  assign zr_data_o = z_rdata;
`ifndef SYNTHESIS
  // A single-ported memory cannot read and write in one clock (the fragment stage's Forward = 0
  // schedule and the arbitration above keep them apart).
  if (SinglePort) begin : g_check_1p
    always_ff @(posedge clk_i) begin
      if (z_re && z_we) $error("htx_fb: depth read and write in one clock on a single port");
      if ((bus_rd_c || vr_gnt_o) && (|c_we)) $error("htx_fb: colour read and write in one clock on a single port");
    end
  end
`endif

  // ---- Response ----------------------------------------------------------------------------------
  logic rsp_valid_q, rsp_err_q, rsp_c_q, rsp_z_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rsp_valid_q <= 1'b0;
      rsp_err_q   <= 1'b0;
      rsp_c_q     <= 1'b0;
      rsp_z_q     <= 1'b0;
    end else begin
      rsp_valid_q <= accept;
      rsp_err_q   <= accept && !in_range;
      rsp_c_q     <= bus_rd_c;
      rsp_z_q     <= bus_rd_z;
    end
  end
  assign rsp_valid_o = rsp_valid_q;
  assign rsp_err_o   = rsp_err_q;
  assign rsp_rdata_o = rsp_c_q ? c_rdata : (rsp_z_q ? 32'(z_rdata) : 32'd0);
  assign vr_data_o   = c_rdata;

  logic unused;
  assign unused = ^{zr_addr_i, w_addr_i, req_addr_i[1:0], req_wdata_i, vr_addr_i, c_page_i};
endmodule
