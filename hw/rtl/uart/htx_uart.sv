// UART peripheral: register block (hw/regs/uart.json), 16-byte TX and RX FIFOs, 8N1 line.
// A DATA write while the TX FIFO is full is not accepted until a byte has left, so software that
// just writes DATA never loses a byte. A DATA read pops the RX FIFO; the popped byte comes from the
// FIFO's registered read port in the response cycle.
module htx_uart #(
  parameter int unsigned FifoDepth = 16
) (
  input  logic        clk_i,
  input  logic        rst_ni,

  input  logic        req_valid_i,
  output logic        req_ready_o,
  input  logic [31:0] req_addr_i,
  input  logic        req_we_i,
  input  logic [3:0]  req_be_i,
  input  logic [31:0] req_wdata_i,
  output logic        rsp_valid_o,
  output logic [31:0] rsp_rdata_o,
  output logic        rsp_err_o,

  input  logic        rx_i,
  output logic        tx_o
);
  localparam int unsigned LevelWidth = $clog2(FifoDepth) + 1;

  logic [11:0] offset;
  logic        accept, is_data, data_write, data_read, tx_stall;
  logic [15:0] divisor_q, divisor;
  logic        loopback_q;
  logic        overrun_q, frame_err_q;

  logic        tx_full, tx_empty, tx_idle, tx_load_q, tx_pop;
  logic [7:0]  tx_byte;
  logic [LevelWidth-1:0] tx_level;
  // (rx_full is read by the simulation harness: a script on stdin is fed as the FIFO has room)
  logic        rx_full /* verilator public_flat_rd */;
  logic        rx_empty, rx_pop;
  // (read by the simulation harness: a DATA read that found no byte, i.e. software waiting for
  // input; a script on stdin that has ended then ends the run)
  logic        rx_empty_read /* verilator public_flat_rd */;
  logic [7:0]  rx_byte;
  logic [LevelWidth-1:0] rx_level;
  logic        rx_valid, rx_frame_err, tx_line, rx_line;
  logic [7:0]  rx_data;

  logic        rsp_valid_q, rsp_from_fifo_q;
  logic [31:0] rsp_rdata_q, rdata_d;

  logic unused_req;
  assign unused_req = ^{req_addr_i[31:12], req_addr_i[1:0], req_be_i[3]};
  // Registers are decoded by word: a byte or half-word access reaches its word's lanes.
  assign offset     = {req_addr_i[11:2], 2'b00};
  assign is_data    = (offset == htx_uart_reg_pkg::UART_DATA_OFFSET);
  assign data_write = is_data && req_we_i && req_be_i[0];
  assign data_read  = is_data && !req_we_i;
  assign tx_stall   = data_write && tx_full;
  assign req_ready_o = !tx_stall;
  assign accept     = req_valid_i && req_ready_o;
  // Only a read that takes the byte's lane pops it: a byte read of RX_EMPTY's lane (DATA + 1)
  // tests for a byte without losing it.
  assign rx_pop     = accept && data_read && req_be_i[0] && !rx_empty;
  assign rx_empty_read = accept && data_read && rx_empty;

  // Divisors below 4 leave no room for mid-bit sampling.
  // (A zero test of the upper bits: Yosys 0.23 builds "< 4" as a 16-bit carry chain.)
  assign divisor = (divisor_q[15:2] == '0) ? 16'd4 : divisor_q;

  htx_fifo_sync #(.Width(8), .Depth(FifoDepth)) u_tx_fifo (
    .clk_i, .rst_ni,
    .push_i (accept && data_write),
    .wdata_i(req_wdata_i[7:0]),
    .pop_i  (tx_pop),
    .rdata_o(tx_byte),
    .full_o (tx_full),
    .empty_o(tx_empty),
    .level_o(tx_level)
  );

  // The FIFO read is registered: pop in one cycle, load the shifter with the byte in the next.
  assign tx_pop = tx_idle && !tx_load_q && !tx_empty;

  htx_uart_tx u_tx (
    .clk_i, .rst_ni,
    .divisor_i(divisor),
    .load_i   (tx_load_q),
    .data_i   (tx_byte),
    .idle_o   (tx_idle),
    .tx_o     (tx_line)
  );

  assign rx_line = loopback_q ? tx_line : rx_i;
  assign tx_o    = loopback_q ? 1'b1 : tx_line;

  htx_uart_rx u_rx (
    .clk_i, .rst_ni,
    .divisor_i  (divisor),
    .rx_i       (rx_line),
    .valid_o    (rx_valid),
    .data_o     (rx_data),
    .frame_err_o(rx_frame_err)
  );

  htx_fifo_sync #(.Width(8), .Depth(FifoDepth)) u_rx_fifo (
    .clk_i, .rst_ni,
    .push_i (rx_valid),
    .wdata_i(rx_data),
    .pop_i  (rx_pop),
    .rdata_o(rx_byte),
    .full_o (rx_full),
    .empty_o(rx_empty),
    .level_o(rx_level)
  );

  always_comb begin
    rdata_d = '0;
    unique case (offset)
      htx_uart_reg_pkg::UART_DATA_OFFSET: begin
        rdata_d[htx_uart_reg_pkg::UART_DATA_RX_EMPTY_LSB] = rx_empty;
      end
      htx_uart_reg_pkg::UART_STATUS_OFFSET: begin
        rdata_d[htx_uart_reg_pkg::UART_STATUS_TX_FULL_LSB]      = tx_full;
        rdata_d[htx_uart_reg_pkg::UART_STATUS_TX_EMPTY_LSB]     = tx_empty;
        rdata_d[htx_uart_reg_pkg::UART_STATUS_TX_IDLE_LSB]      = tx_empty && tx_idle && !tx_load_q;
        rdata_d[htx_uart_reg_pkg::UART_STATUS_RX_VALID_LSB]     = !rx_empty;
        rdata_d[htx_uart_reg_pkg::UART_STATUS_RX_FULL_LSB]      = rx_full;
        rdata_d[htx_uart_reg_pkg::UART_STATUS_RX_OVERRUN_LSB]   = overrun_q;
        rdata_d[htx_uart_reg_pkg::UART_STATUS_RX_FRAME_ERR_LSB] = frame_err_q;
      end
      htx_uart_reg_pkg::UART_CTRL_OFFSET: begin
        rdata_d[htx_uart_reg_pkg::UART_CTRL_DIVISOR_LSB +: 16] = divisor_q;
        rdata_d[htx_uart_reg_pkg::UART_CTRL_LOOPBACK_LSB]      = loopback_q;
      end
      htx_uart_reg_pkg::UART_LEVEL_OFFSET: begin
        rdata_d[htx_uart_reg_pkg::UART_LEVEL_TX_LSB +: LevelWidth] = tx_level;
        rdata_d[htx_uart_reg_pkg::UART_LEVEL_RX_LSB +: LevelWidth] = rx_level;
      end
      default: ;
    endcase
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      divisor_q       <= 16'(htx_uart_reg_pkg::UART_CTRL_DIVISOR_RESET);
      loopback_q      <= 1'b0;
      overrun_q       <= 1'b0;
      frame_err_q     <= 1'b0;
      tx_load_q       <= 1'b0;
      rsp_valid_q     <= 1'b0;
      rsp_from_fifo_q <= 1'b0;
      rsp_rdata_q     <= '0;
    end else begin
      tx_load_q       <= tx_pop;
      rsp_valid_q     <= accept;
      rsp_from_fifo_q <= rx_pop;
      if (accept && !req_we_i) rsp_rdata_q <= rdata_d;

      if (accept && req_we_i) begin
        unique case (offset)
          htx_uart_reg_pkg::UART_STATUS_OFFSET: begin
            if (req_be_i[0] && req_wdata_i[htx_uart_reg_pkg::UART_STATUS_RX_OVERRUN_LSB]) begin
              overrun_q <= 1'b0;
            end
            if (req_be_i[0] && req_wdata_i[htx_uart_reg_pkg::UART_STATUS_RX_FRAME_ERR_LSB]) begin
              frame_err_q <= 1'b0;
            end
          end
          htx_uart_reg_pkg::UART_CTRL_OFFSET: begin
            if (req_be_i[0]) divisor_q[7:0]  <= req_wdata_i[7:0];
            if (req_be_i[1]) divisor_q[15:8] <= req_wdata_i[15:8];
            if (req_be_i[2]) loopback_q      <= req_wdata_i[htx_uart_reg_pkg::UART_CTRL_LOOPBACK_LSB];
          end
          default: ;
        endcase
      end
      // After the write-one-to-clear above, so an error in the clearing cycle is not lost.
      if (rx_valid && rx_full) overrun_q <= 1'b1;
      if (rx_frame_err)        frame_err_q <= 1'b1;
    end
  end

  assign rsp_valid_o = rsp_valid_q;
  assign rsp_rdata_o = rsp_from_fifo_q ? {24'b0, rx_byte} : rsp_rdata_q;
  assign rsp_err_o   = 1'b0;
endmodule
