// A register block's bus slave port with two clocks of latency (the timer's and the video unit's):
// always ready, it registers each request as it is accepted and presents it to the block in the
// next clock (act_offset_o; act_write_o only for a whole-word write, partial writes are ignored),
// takes the block's read data in that clock and answers in the clock after. So a block's write enables
// come from flip-flops, and a read right behind a write sees it.
module htx_reg_port (
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

  output logic        act_write_o,    // a whole-word write acts in this clock
  output logic [11:0] act_offset_o,   // its offset in the 4 KiB block
  output logic [31:0] act_wdata_o,
  input  logic [31:0] rdata_i         // the block's read data at act_offset_o
);
  logic        act_q, rsp_valid_q;  // act_q: a request acts in this clock
  logic [31:0] rsp_rdata_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      act_q        <= 1'b0;
      act_write_o  <= 1'b0;
      act_offset_o <= '0;
      act_wdata_o  <= '0;
      rsp_valid_q  <= 1'b0;
      rsp_rdata_q  <= '0;
    end else begin
      act_q       <= req_valid_i;
      act_write_o <= req_valid_i && req_we_i && (req_be_i == 4'b1111);
      if (req_valid_i) begin
        act_offset_o <= {req_addr_i[11:2], 2'b00};  // by word: a narrower read gets its word's lanes
        act_wdata_o  <= req_wdata_i;
      end
      rsp_valid_q <= act_q;
      if (act_q && !act_write_o) rsp_rdata_q <= rdata_i;
    end
  end
  assign req_ready_o = 1'b1;
  assign rsp_valid_o = rsp_valid_q;
  assign rsp_rdata_o = rsp_rdata_q;
  assign rsp_err_o   = 1'b0;

  logic unused_addr;
  assign unused_addr = ^{req_addr_i[31:12], req_addr_i[1:0]};
endmodule
