// Base-2 logarithm (model Log2Unit): log2(x) = p 2^F + T[i] with p the leading-one index of x > 0
// and i the IdxBits bits below it (truncated); T[i] = round(2^F log2(1 + (i + 1/2) / 2^IdxBits)),
// built at elaboration by the model's exact repeated squaring. Combinational. x = 0 gives p = 0.
module htx_tex_log2 #(
  parameter int unsigned InW     = 64,
  parameter int unsigned IdxBits = 10,
  parameter int unsigned F       = 10,
  parameter int unsigned OutW    = 18   // unsigned result width: covers (InW - 1) 2^F + 2^F
) (
  input  logic [InW-1:0]  x_i,
  output logic [OutW-1:0] log2_o
);
  localparam int unsigned N  = 2 ** IdxBits;
  localparam int unsigned TW = F + 1;   // entries reach 2^F

  function automatic logic [TW-1:0] entry(input int unsigned i);
    logic [127:0] y;
    logic [63:0]  acc;
    y   = (128'd1 << 62) + (128'(2 * i + 1) << (62 - IdxBits - 1));
    acc = '0;
    for (int b = 0; b < F + 8; b++) begin
      y   = (y * y) >> 62;
      acc = acc << 1;
      if (y >= (128'd2 << 62)) begin
        acc = acc | 64'd1;
        y   = y >> 1;
      end
    end
    entry = TW'((acc + 64'd128) >> 8);
  endfunction

  logic [N*TW-1:0] table_flat;
  for (genvar i = 0; i < N; i++) begin : g_table
    localparam logic [TW-1:0] Entry = entry(i);
    assign table_flat[i*TW +: TW] = Entry;
  end

  logic [6:0]         p;
  logic [InW-1:0]     below;
  logic [IdxBits-1:0] idx;
  always_comb begin
    p = '0;
    for (int k = 0; k < InW; k++) begin
      if (x_i[k]) p = 7'(k);
    end
  end
  assign below = x_i & ~(InW'(1) << p);
  always_comb begin
    if (32'(p) >= IdxBits) idx = IdxBits'(below >> (32'(p) - IdxBits));
    else                   idx = IdxBits'(below << (IdxBits - 32'(p)));
  end
  assign log2_o = (OutW'(p) << F) + OutW'(table_flat[32'(idx)*TW +: TW]);
endmodule
