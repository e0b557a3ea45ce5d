// Load/store datapath (combinational): byte enables and store data placed on its lanes for the
// request (misalignment is checked in decode); lane selection and sign/zero extension for the
// response.
module htx_cpu_lsu (
  // request side (execute stage)
  input  logic [1:0]  req_size_i,     // funct3[1:0] of the load or store: byte, half, word
  input  logic [1:0]  req_offset_i,   // address bits [1:0]
  input  logic [31:0] req_data_i,     // rs2 of a store
  output logic [3:0]  req_be_o,
  output logic [31:0] req_wdata_o,
  // response side (write-back stage)
  input  logic [2:0]  rsp_funct3_i,
  input  logic [1:0]  rsp_offset_i,   // address bits [1:0] of the load
  input  logic [31:0] rsp_rdata_i,    // whole bus word
  output logic [31:0] rsp_value_o
);

  always_comb begin
    unique case (req_size_i)
      2'b00: begin
        req_be_o         = 4'b0001 << req_offset_i;
        req_wdata_o      = {4{req_data_i[7:0]}};
      end
      2'b01: begin
        req_be_o         = req_offset_i[1] ? 4'b1100 : 4'b0011;
        req_wdata_o      = {2{req_data_i[15:0]}};
      end
      default: begin
        req_be_o         = 4'b1111;
        req_wdata_o      = req_data_i;
      end
    endcase
  end

  // Response, arranged for depth (the bus word arrives late in W and feeds decode's forwarding):
  // the fill bit (sign or zero) is chosen first from the four candidate sign bits, then every
  // result bit is one LUT level after it. Word loads have offset 0 and half-word loads offset 0 or
  // 2 (decode traps the others), so bits [7:0] are always the lane at the offset.
  logic       rsp_word, rsp_byte;
  (* keep *) logic rsp_fill;
  assign rsp_word = rsp_funct3_i[1];
  assign rsp_byte = (rsp_funct3_i[1:0] == 2'b00);
  always_comb begin
    if (rsp_byte) begin
      unique case (rsp_offset_i)
        2'b00:   rsp_fill = rsp_rdata_i[7];
        2'b01:   rsp_fill = rsp_rdata_i[15];
        2'b10:   rsp_fill = rsp_rdata_i[23];
        default: rsp_fill = rsp_rdata_i[31];
      endcase
    end else begin
      rsp_fill = rsp_offset_i[1] ? rsp_rdata_i[31] : rsp_rdata_i[15];
    end
    rsp_fill = rsp_fill && !rsp_funct3_i[2];
  end

  always_comb begin
    unique case (rsp_offset_i)
      2'b00:   rsp_value_o[7:0] = rsp_rdata_i[7:0];
      2'b01:   rsp_value_o[7:0] = rsp_rdata_i[15:8];
      2'b10:   rsp_value_o[7:0] = rsp_rdata_i[23:16];
      default: rsp_value_o[7:0] = rsp_rdata_i[31:24];
    endcase
    rsp_value_o[15:8]  = rsp_byte ? {8{rsp_fill}} :
                         rsp_offset_i[1] ? rsp_rdata_i[31:24] : rsp_rdata_i[15:8];
    rsp_value_o[31:16] = rsp_word ? rsp_rdata_i[31:16] : {16{rsp_fill}};
  end

endmodule
