// A board's reset: held for the first 16 clocks after configuration (the FPGA's flip-flops start
// at zero) and while the board's reset button is pressed, then released synchronously, 16 clocks
// after the button. The button is synchronised through two flip-flops first.
module htx_board_reset (
  input  logic clk_i,
  input  logic button_ni,   // the board's button, 0 while pressed (asynchronous)
  output logic rst_no       // the SoC's reset, active low
);
  logic [1:0] button_sync_q = 2'b00;
  logic [3:0] count_q = 4'd0;
  logic       rst_n_q = 1'b0;
  always_ff @(posedge clk_i) begin
    button_sync_q <= {button_sync_q[0], button_ni};
    if (!button_sync_q[1]) begin
      count_q <= 4'd0;
      rst_n_q <= 1'b0;
    end else if (count_q != 4'hF) begin
      count_q <= count_q + 4'd1;
      rst_n_q <= 1'b0;
    end else begin
      rst_n_q <= 1'b1;
    end
  end
  assign rst_no = rst_n_q;
endmodule
