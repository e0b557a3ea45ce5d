// 8N1 transmitter: start bit, eight data bits LSB first, one stop bit; divisor_i clocks per bit.
module htx_uart_tx (
  input  logic        clk_i,
  input  logic        rst_ni,
  input  logic [15:0] divisor_i,   // clocks per bit, >= 4
  input  logic        load_i,      // start sending data_i (only when idle_o)
  input  logic [7:0]  data_i,
  output logic        idle_o,
  output logic        tx_o
);
  logic [9:0]  shift_q;     // {stop, data[7:0], start}, shifted out LSB first
  logic [3:0]  bits_q;      // bits still to send
  logic [15:0] baud_q;      // clocks left in this bit, the last one being 1 (loading divisor_i
                            // itself, not divisor_i - 1, saves a subtractor)

  assign idle_o = (bits_q == '0);
  assign tx_o   = idle_o ? 1'b1 : shift_q[0];

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      shift_q <= '1;
      bits_q  <= '0;
      baud_q  <= 16'd1;
    end else if (idle_o) begin
      if (load_i) begin
        shift_q <= {1'b1, data_i, 1'b0};
        bits_q  <= 4'd10;
        baud_q  <= divisor_i;
      end
    end else if (baud_q == 16'd1) begin
      shift_q <= {1'b1, shift_q[9:1]};
      bits_q  <= bits_q - 1'b1;
      baud_q  <= divisor_i;
    end else begin
      baud_q <= baud_q - 1'b1;
    end
  end
endmodule
