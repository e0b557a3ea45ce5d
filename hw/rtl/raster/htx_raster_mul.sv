// Signed multiplier of the raster setup with a start/done handshake; p_o = (a b) >>> extra_i, or
// (-(a b)) >>> extra_i with neg_i (not DigitSerial, where neg_i must be 0): the iterative form
// subtracts where it would add, so a caller negating a product pays one LUT, not a negator.
// Iterative = 0: the product (and its shift) is combinational and done_o follows start_i in the
// same cycle (the `full` configuration: one product per clock). Iterative = 1: one bit of b per
// clock, BWidth clocks, then extra_i clocks of right shift in the same registers (the `icebreaker`
// configuration trades clocks for LUTs and DSPs). DigitSerial = 1 (with Iterative = 0): one digit
// product per clock on one DSP, or with b whole one 15-bit digit of a per clock on about
// BWidth / 16 DSPs (g_digits; the `icebreaker` divider). The operands must stay stable while
// start_i is held (DigitSerial reads them on every clock of the product; Iterative takes them,
// neg_i and extra_i at the start); done_o is a one-cycle pulse. p_o is the product in the clock
// done_o pulses (DigitSerial clears it after that clock; the other forms hold it until the next start).
// abort_i drops a product in progress, so a unit aborted mid-product does not take its stale
// result for the next one.
module htx_raster_mul #(
  parameter int unsigned AWidth    = 32,
  parameter int unsigned BWidth    = 32,
  parameter bit          Iterative = 1'b0,
  parameter bit          DigitSerial = 1'b0,
  parameter bit          DigitSplitB = 1'b1,  // DigitSerial: b in digits too (1 DSP), or whole
  parameter int unsigned ExtraW    = 8
) (
  input  logic                             clk_i,
  input  logic                             rst_ni,
  input  logic                             abort_i,  // drop a product in progress (Iterative)
  input  logic                             start_i,
  input  logic signed [AWidth-1:0]         a_i,
  input  logic signed [BWidth-1:0]         b_i,
  input  logic                             neg_i,    // the product negated (with the operands)
  input  logic [ExtraW-1:0]                extra_i,  // p_o = (a b) >>> extra_i
  output logic                             done_o,
  output logic signed [AWidth+BWidth-1:0]  p_o
);
  localparam int unsigned PWidth = AWidth + BWidth;

  if (!Iterative && DigitSerial) begin : g_digits
    // a is cut into 15-bit digits, and b too when DigitSplitB (else b is one digit); each digit is
    // a signed number one bit wider: the lower digits are non-negative (a zero on top), the top
    // digit of each operand carries its sign. So every partial product is one signed product of
    // the same shape (16 x 16: one SB_MAC16; 16 x BWidth with b whole) and no sign correction is
    // needed. Products are summed column by column (digit positions i + j = k, k rising): when a
    // column is complete its low 15 bits are final and shift out into low_q, and the carry
    // (acc >>> 15) starts the next column. One digit pair per clock, the first in the clock that
    // takes start_i: NA * NB clocks, done_o in the next. Needs two columns at least (NA + NB > 2).
    localparam int unsigned DigW = 15;
    localparam int unsigned BDW  = DigitSplitB ? DigW : BWidth;  // b's digit width
    localparam int unsigned NA   = (AWidth + DigW - 1) / DigW;
    localparam int unsigned NB   = (BWidth + BDW - 1) / BDW;
    localparam int unsigned NC   = NA + NB - 1;
    localparam int unsigned LowW = DigW * (NC - 1);
    localparam int unsigned AccW = (DigW + 1) + (BDW + 1) + $clog2(NB + 1) + 1;
    localparam int unsigned IW   = (NA > 1) ? $clog2(NA) : 1;
    localparam int unsigned JW   = (NB > 1) ? $clog2(NB) : 1;
    localparam int unsigned KW   = $clog2(NA + NB) + 1;

    logic signed [NA*DigW-1:0] a_ext;
    logic signed [NB*BDW-1:0]  b_ext;
    assign a_ext = (NA*DigW)'(a_i);
    assign b_ext = (NB*BDW)'(b_i);

    logic                   busy_q, done_q, newcol_q, go;
    logic [IW-1:0]          i_q;
    logic [JW-1:0]          j_q;
    logic signed [AccW-1:0] acc_q, base;
    logic [LowW-1:0]        low_q;
    logic signed [DigW:0]   da;
    logic signed [BDW:0]    db;
    logic signed [DigW+BDW+1:0] prod;
    always_comb begin
      da = '0;
      for (int i = 0; i < NA; i++) begin
        if (32'(i_q) == i) da = (i == NA - 1) ? (DigW+1)'($signed(a_ext[DigW*i +: DigW]))
                                              : $signed({1'b0, a_ext[DigW*i +: DigW]});
      end
      db = '0;
      for (int j = 0; j < NB; j++) begin
        if (32'(j_q) == j) db = (j == NB - 1) ? (BDW+1)'($signed(b_ext[BDW*j +: BDW]))
                                              : $signed({1'b0, b_ext[BDW*j +: BDW]});
      end
    end
    assign prod = da * db;
    // Idle, i_q = j_q = 0: the clock that takes start_i multiplies the first pair onto zero. acc_q
    // is zero then: it has no reset and is cleared in every clock without a product after done_o's
    // (the callers take p_o in that clock), which is its flip-flops' synchronous reset, so the
    // first pair needs no zero base. With b whole (NB = 1) every digit starts a column.
    // (base is written with if/else: in one ?: with an unsigned '0 the whole expression would be
    // unsigned and >>> a logical shift.)
    assign go = !busy_q && !done_q && start_i;
    if (NB == 1) begin : g_base_col
      assign base = acc_q >>> DigW;
    end else begin : g_base
      always_comb begin
        if (newcol_q) base = acc_q >>> DigW;
        else          base = acc_q;
      end
    end

    // Next digit pair: along the column (i up, j down) or the start of the next one.
    logic          col_end, last;
    logic [KW-1:0] k_next;
    logic [IW-1:0] i_next;
    logic [JW-1:0] j_next;
    assign col_end = (32'(i_q) == NA - 1) || (j_q == '0);
    assign last    = (32'(i_q) == NA - 1) && (32'(j_q) == NB - 1);
    always_comb begin
      k_next = KW'(i_q) + KW'(j_q) + 1'b1;
      if (col_end) begin
        j_next = (32'(k_next) + 1 < NB) ? JW'(k_next) : JW'(NB - 1);
        i_next = IW'(k_next - KW'(j_next));
      end else begin
        i_next = i_q + 1'b1;
        j_next = j_q - 1'b1;
      end
    end

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        busy_q   <= 1'b0;
        done_q   <= 1'b0;
        newcol_q <= 1'b0;
        i_q      <= '0;
        j_q      <= '0;
        low_q    <= '0;
      end else if (abort_i) begin
        busy_q <= 1'b0;
        done_q <= 1'b0;
        i_q    <= '0;
        j_q    <= '0;
      end else begin
        done_q <= 1'b0;
        if (go || busy_q) begin
          if (busy_q && newcol_q) low_q <= {acc_q[DigW-1:0], low_q[LowW-1:DigW]};
          newcol_q <= col_end;
          if (last) begin
            busy_q <= 1'b0;
            done_q <= 1'b1;
            i_q    <= '0;
            j_q    <= '0;
          end else begin
            busy_q <= 1'b1;
            i_q    <= i_next;
            j_q    <= j_next;
          end
        end
      end
    end

    always_ff @(posedge clk_i) begin
      if (abort_i || !(go || busy_q)) begin
        acc_q <= '0;
      end else begin
        acc_q <= base + AccW'(prod);
      end
    end

    logic unused_neg;
    assign unused_neg = neg_i;
    logic signed [PWidth-1:0] prod_all;
    assign prod_all = PWidth'({acc_q, low_q});
    assign done_o   = done_q;
    assign p_o      = prod_all >>> extra_i;
  end else if (!Iterative) begin : g_comb
    logic unused;
    logic signed [PWidth-1:0] ab, prod;
    assign unused = ^{clk_i, rst_ni, abort_i};
    assign done_o = start_i;
    assign ab     = PWidth'(a_i) * PWidth'(b_i);
    assign prod   = neg_i ? -ab : ab;
    assign p_o    = prod >>> extra_i;
  end else begin : g_iter
    // The textbook sequential signed multiplier: {h, l} starts as {0, b}; each clock adds a to h
    // when l's lowest bit is set (subtracts it for b's sign bit, the last) and shifts {h, l} right
    // by one, arithmetically. BWidth clocks, one (AWidth + 1)-bit adder, no DSP, no magnitudes.
    // extra_i more clocks go on shifting with nothing added: a right shift of the product for free
    // in the same registers (the plane unit's rounding shift, instead of a barrel shifter).
    localparam int unsigned CntW = $clog2(BWidth + 2**ExtraW);

    logic                     busy_q, done_q, last, in_mul, finish, neg_q;
    logic [CntW-1:0]          cnt_q;
    logic signed [AWidth:0]   h_q, addend, sum;
    logic [BWidth-1:0]        l_q;
    // a, neg_i and extra_i are taken at the start, like b: the adder then starts from registers,
    // not from the caller's operand multiplexers (`icebreaker`'s setup, docs/raster.md).
    logic signed [AWidth-1:0] a_q;
    logic [ExtraW-1:0]        extra_q;

    assign in_mul = (cnt_q < CntW'(BWidth));
    assign last   = (cnt_q == CntW'(BWidth - 1));
    assign finish = (cnt_q == CntW'(BWidth - 1) + CntW'(extra_q));
    assign addend = (l_q[0] && in_mul) ? (AWidth + 1)'(a_q) : '0;
    // h + addend, or h - addend for b's sign bit: one adder (htx_raster_addsub), not two. A
    // negated product swaps the two: -(a b) = sum of -b_i a 2^i + b_(B-1) a 2^(B-1), and its
    // partial sums are bounded as the positive product's are.
    htx_raster_addsub #(.W(AWidth + 1)) u_addsub (
      .a_i(h_q), .b_i(addend), .sub_i(last ^ neg_q), .sum_o(sum)
    );

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        busy_q <= 1'b0;
        done_q <= 1'b0;
        cnt_q  <= '0;
        h_q    <= '0;
        l_q    <= '0;
        neg_q  <= 1'b0;
      end else if (abort_i) begin
        busy_q <= 1'b0;
        done_q <= 1'b0;
      end else begin
        done_q <= 1'b0;
        if (!busy_q && !done_q && start_i) begin
          busy_q <= 1'b1;
          cnt_q  <= '0;
          h_q    <= '0;
          l_q    <= b_i;
          neg_q  <= neg_i;
        end else if (busy_q) begin
          {h_q, l_q} <= {sum[AWidth], sum, l_q[BWidth-1:1]};
          cnt_q      <= cnt_q + 1'b1;
          if (finish) begin
            busy_q <= 1'b0;
            done_q <= 1'b1;
          end
        end
      end
    end

    always_ff @(posedge clk_i) begin
      if (!busy_q && !done_q && start_i) begin
        a_q     <= a_i;
        extra_q <= extra_i;
      end
    end

    assign done_o = done_q;
    assign p_o    = {h_q[AWidth-1:0], l_q};
  end
endmodule
