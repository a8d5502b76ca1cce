// The pipelined M-way interleaved unit (docs/hardware.md, "Pipelined"): ps_interleave's lanes with
// double-buffered span registers. The load clock fills a shadow bank (S + j*dI per lane, M*dI, the
// length) while the active bank still shades the previous span; in the clock after the active span's
// last pixels the shadow bank is copied in, so consecutive spans follow each other without a load
// clock: ceil(L/M) clocks per span once the pipeline is full. Filling it costs 2 clocks (load, copy)
// when the unit starts or has run dry. The cost: a second bank of M + 1 W-bit registers and a length.
/* verilator lint_off UNUSEDSIGNAL */
module ps_pipelined #(
  parameter I = 12,
  parameter F = 12,
  parameter LEN = 13,
  parameter M = 4
) (
  input  wire             clk,
  input  wire             rst,
  input  wire             load,
  output wire             ready,
  input  wire [I+F-1:0]   s_in,
  input  wire [I+F-1:0]   e_in,
  input  wire [I+F-1:0]   step_in,
  input  wire [I+F-1:0]   lane_step_in,
  input  wire [LEN-1:0]   length_in,
  output wire [M-1:0]     valid,
  output wire [M*LEN-1:0] x,
  output wire [M*(I+F)-1:0] value,
  output wire [M*8-1:0]   level
);
  localparam W = I + F;
  /* verilator lint_off WIDTH */  // the lane count, truncated to the length's bits
  localparam [LEN-1:0] LANES = M;  // pixels per clock
  /* verilator lint_on WIDTH */
  wire [(M+1)*W-1:0] mult;
  ps_multiples #(.W(W), .N(M)) multiples (.step(step_in), .mult(mult));
  // Shadow bank: the next span, loaded while the active bank runs.
  reg [M*W-1:0] next_r;
  reg [W-1:0] next_lane_step;
  reg [LEN-1:0] next_length;
  reg full;
  // Active bank.
  reg [M*W-1:0] r;
  reg [W-1:0] lane_step;
  reg [LEN-1:0] first, rest;
  reg busy;
  wire last = busy && rest <= LANES;      // the active span's last clock
  wire take = full && (!busy || last);    // the shadow bank moves in at this clock's edge
  assign ready = (!full || take) && !rst;  // in reset `load` is ignored: never offer to take it
  wire accept = load && ready;
  always @(posedge clk) begin
    if (rst) begin
      full <= 1'b0;
      busy <= 1'b0;
    end else begin
      if (accept) begin
        next_lane_step <= mult[M*W +: W];
        next_length <= length_in;
        full <= 1'b1;
      end else if (take) begin
        full <= 1'b0;
      end
      if (take) begin
        lane_step <= next_lane_step;
        first <= {LEN{1'b0}};
        rest <= next_length;
        busy <= 1'b1;
      end else if (busy) begin
        first <= first + LANES;
        rest <= rest - LANES;
        busy <= !last;
      end
    end
  end
  genvar j;
  generate
    for (j = 0; j < M; j = j + 1) begin : lane
      /* verilator lint_off WIDTH */
      localparam [LEN-1:0] K = j;  // the lane's pixel after `first`
      /* verilator lint_on WIDTH */
      always @(posedge clk) begin
        if (accept) next_r[j*W +: W] <= j == 0 ? s_in : s_in + mult[j*W +: W];
        if (take) r[j*W +: W] <= next_r[j*W +: W];
        else if (busy) r[j*W +: W] <= r[j*W +: W] + lane_step;
      end
      assign valid[j] = busy && rest > K;
      assign x[j*LEN +: LEN] = first + K;
      assign value[j*W +: W] = r[j*W +: W];
      ps_level #(.I(I), .F(F)) out (.v(r[j*W +: W]), .level(level[j*8 +: 8]));
    end
  endgenerate
endmodule
