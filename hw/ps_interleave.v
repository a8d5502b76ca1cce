// The M-way interleaved unit (docs/hardware.md; M = 2 is the even/odd unit): M code interpolators,
// lane j starting at S + j*dI and stepping by M*dI, one pixel each per clock. The multiples j*dI and
// M*dI come from ps_multiples (shifts, one adder per odd multiple: the sources' RG3 for 2dI); the load
// clock adds them to S (M - 1 adders). OWN = 1: M*dI is the lane_step_in register (rounded by setup on
// its own, interleave:M:own). A lane whose pixel lies past the span is blocked (valid low).
/* verilator lint_off UNUSEDSIGNAL */
module ps_interleave #(
  parameter I = 12,
  parameter F = 12,
  parameter LEN = 13,
  parameter M = 4,
  parameter OWN = 0
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
  /* verilator lint_off WIDTH */  // the lane counts, truncated to the length's bits
  localparam [LEN-1:0] LANES = M;  // pixels per clock
  /* verilator lint_on WIDTH */
  wire [(M+1)*W-1:0] mult;
  ps_multiples #(.W(W), .N(M)) multiples (.step(step_in), .mult(mult));
  reg [M*W-1:0] r;
  reg [W-1:0] lane_step;
  reg [LEN-1:0] first, rest;  // the span's pixel at lane 0; pixels left from it on
  reg busy;
  assign ready = !busy && !rst;  // in reset `load` is ignored: never offer to take it
  always @(posedge clk) begin
    if (rst) begin
      busy <= 1'b0;
    end else if (load && ready) begin
      lane_step <= OWN != 0 ? lane_step_in : mult[M*W +: W];
      first <= {LEN{1'b0}};
      rest <= length_in;
      busy <= 1'b1;
    end else if (busy) begin
      first <= first + LANES;
      rest <= rest - LANES;
      busy <= rest > LANES;
    end
  end
  genvar j;
  generate
    for (j = 0; j < M; j = j + 1) begin : lane
      /* verilator lint_off WIDTH */
      localparam [LEN-1:0] K = j;  // the lane's pixel after `first`
      /* verilator lint_on WIDTH */
      always @(posedge clk) begin
        if (load && ready) r[j*W +: W] <= j == 0 ? s_in : s_in + mult[j*W +: W];
        else if (busy) r[j*W +: W] <= r[j*W +: W] + lane_step;
      end
      assign valid[j] = busy && rest > K;
      assign x[j*LEN +: LEN] = first + K;
      assign value[j*W +: W] = r[j*W +: W];
      ps_level #(.I(I), .F(F)) out (.v(r[j*W +: W]), .level(level[j*8 +: 8]));
    end
  endgenerate
endmodule
