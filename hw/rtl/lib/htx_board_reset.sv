// A board's reset: held for the first 256 clocks after configuration (the FPGA's flip-flops start
// at zero) and while the board's reset button is pressed, then released synchronously, 256 clocks
// after the button. The button is synchronised through two flip-flops first. 256 clocks (21 us at
// 12 MHz, 10 us at 25 MHz) cover the iCE40's block RAMs, which read 0 for about 3 us after
// configuration: the CPU's first fetches would be of zeros.
module htx_board_reset (
  input  logic clk_i,
  input  logic button_ni,   // the board's button, 0 while pressed (asynchronous)
  output logic rst_no       // the SoC's reset, active low
);
  logic [1:0] button_sync_q = 2'b00;
  logic [7:0] count_q = 8'd0;
  logic       rst_n_q = 1'b0;
  always_ff @(posedge clk_i) begin
    button_sync_q <= {button_sync_q[0], button_ni};
    if (!button_sync_q[1]) begin
      count_q <= 8'd0;
      rst_n_q <= 1'b0;
    end else if (count_q != 8'hFF) begin
      count_q <= count_q + 8'd1;
      rst_n_q <= 1'b0;
    end else begin
      rst_n_q <= 1'b1;
    end
  end
  assign rst_no = rst_n_q;
endmodule
