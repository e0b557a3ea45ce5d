// 8N1 receiver. The line is synchronised through two flops; a falling edge starts a byte, which is
// confirmed at the middle of the start bit (shorter glitches are ignored), and each data bit and the
// stop bit are sampled at their middles. A 0 stop bit reports a framing error instead of a byte.
// Only an edge starts a byte, not a low level: after a framing error on a break (the line held low),
// the receiver waits for the line to come back high rather than framing the break again and again
// and taking the bits around its end for a byte.
module htx_uart_rx (
  input  logic        clk_i,
  input  logic        rst_ni,
  input  logic [15:0] divisor_i,   // clocks per bit, >= 4
  input  logic        rx_i,        // asynchronous serial input, idle high
  output logic        valid_o,     // one-cycle pulse: data_o received
  output logic [7:0]  data_o,
  output logic        frame_err_o  // one-cycle pulse: stop bit was 0, byte dropped
);
  typedef enum logic [1:0] {
    RxIdle,
    RxStart,
    RxData,
    RxStop
  } rx_state_e;

  rx_state_e   state_q, state_d;
  logic [2:0]  sync_q;    // [1] the synchronised line, [2] its level a clock before
  logic        line, line_fell;
  logic [15:0] baud_q, baud_d;  // clocks to the next sample, the last one being 1 (loading
                                // divisor_i and divisor_i / 2, not one less, needs no subtractors)
  logic [2:0]  bit_q, bit_d;
  logic [7:0]  data_q, data_d;
  logic        tick;

  assign line      = sync_q[1];
  assign line_fell = sync_q[2] && !sync_q[1];
  assign tick = (baud_q == 16'd1);

  always_comb begin
    state_d     = state_q;
    baud_d      = tick ? baud_q : baud_q - 1'b1;
    bit_d       = bit_q;
    data_d      = data_q;
    valid_o     = 1'b0;
    frame_err_o = 1'b0;
    unique case (state_q)
      RxIdle: begin
        if (line_fell) begin
          state_d = RxStart;
          baud_d  = {1'b0, divisor_i[15:1]};  // to the middle of the start bit
        end
      end
      RxStart: begin
        if (tick) begin
          state_d = line ? RxIdle : RxData;
          baud_d  = divisor_i;
          bit_d   = '0;
        end
      end
      RxData: begin
        if (tick) begin
          data_d = {line, data_q[7:1]};
          bit_d  = bit_q + 1'b1;
          baud_d = divisor_i;
          if (bit_q == 3'd7) state_d = RxStop;
        end
      end
      RxStop: begin
        if (tick) begin
          state_d     = RxIdle;
          valid_o     = line;
          frame_err_o = !line;
        end
      end
      default: state_d = RxIdle;
    endcase
  end

  assign data_o = data_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= RxIdle;
      sync_q  <= '1;
      baud_q  <= 16'd1;
      bit_q   <= '0;
      data_q  <= '0;
    end else begin
      state_q <= state_d;
      sync_q  <= {sync_q[1:0], rx_i};
      baud_q  <= baud_d;
      bit_q   <= bit_d;
      data_q  <= data_d;
    end
  end
endmodule
