// The reciprocal unit's seed table (docs/model.md §4): the DasSarma-Matula midpoint table with K
// index bits and G guard bits, entry i = round(2^(2K+G+2) / (2^(K+1) + 2i + 1)) (the odd divisor
// never ties), K + G + 1 bits. The read is registered without a reset (entry_o follows index_i
// one clock after a clock with en_i set), so Yosys maps the table to one block RAM; with an
// asynchronous reset it would be a LUT ROM (about 200 LUT4 for K = 8).
module htx_recip_table #(
  parameter int unsigned K = 10,
  parameter int unsigned G = 2
) (
  input  logic             clk_i,
  input  logic             en_i,
  input  logic [K-1:0]     index_i,
  output logic [K+G:0]     entry_o
);
  localparam int unsigned EntryW = K + G + 1;

  function automatic logic [EntryW-1:0] table_entry(input int unsigned i);
    logic [63:0] num, den;
    num = 64'd1 << (2 * K + G + 2);
    den = (64'd1 << (K + 1)) + 64'(2 * i + 1);
    table_entry = EntryW'((2 * num + den) / (2 * den));
  endfunction

  logic [EntryW-1:0] rom [2**K];
  initial begin
    for (int unsigned i = 0; i < 2**K; i++) rom[i] = table_entry(i);
  end

  always_ff @(posedge clk_i) begin
    if (en_i) entry_o <= rom[index_i];
  end
endmodule
