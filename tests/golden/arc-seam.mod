MODULE ArcSeam
    ! generator: gen-rapid 0.1.0
    ! cell: arc-seam.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: extensile
    ! grid (deg): 1.000
    ! clearance (mm): 10.0
    ! base: [0.0, -850.0, 0.0] yaw: 90.000
    ! tool: tTorch (declared below; collision shapes: mount, neck, nozzle)
    ! wobj: wobjTrunk (declared below; robtargets are in its user frame)
    ! frames: robtargets and the user frame are given in the cell frame; they mean the cell's poses only if the controller's base frame is the base and yaw above
    ! moves: 14
    ! min clearance (mm): 10.0
    ! estimated time (s): 31.26
    ! cycle: open: the routine ends at home2, not where it starts (home); motion.cycle: true closes it
    ! zoned vias: 0 of 9 (via zone fine)
    ! the paper's method alone: 17 moves, 31.89 s

    PERS tooldata tTorch := [TRUE,[[116.673,0.000,336.673],[0.923879539,0.000000000,0.382683416,0.000000000]],[2.500,[0.000,0.000,120.000],[1,0,0,0],0,0,0]];
    PERS wobjdata wobjTrunk := [FALSE,TRUE,"",[[-830.000,-380.000,100.000],[1.000000000,0.000000000,0.000000000,0.000000000]],[[0,0,0],[1,0,0,0]]];

    CONST jointtarget home := [[90.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_01 := [[64.688,-28.219,20.250,3.482,37.473,-50.131],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_02 := [[59.980,-32.863,18.051,3.610,37.746,-51.963],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_03 := [[53.241,-28.044,20.098,4.619,39.912,-66.491],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_04 := [[40.623,-7.124,36.148,7.984,47.133,-114.932],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget S1_rt := [[330.000,280.000,0.000],[0.183012701,-0.683012702,-0.683012702,-0.183012701],[0,0,-2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget S2_via := [[388.579,421.421,0.000],[0.183012701,-0.683012702,-0.683012702,-0.183012701],[0,0,-2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget S2_rt := [[530.000,480.000,0.000],[0.183012701,-0.683012702,-0.683012702,-0.183012701],[0,0,-2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_01 := [[15.000,7.000,60.000,5.400,56.716,-163.918],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_02 := [[9.000,1.000,59.000,5.084,55.149,-154.303],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_03 := [[-28.766,-32.406,24.141,2.620,42.961,-79.526],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_04 := [[-49.000,-39.000,13.000,1.539,37.612,-46.702],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_05 := [[-62.703,-26.297,24.172,1.298,36.423,-39.406],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget home2 := [[-90.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        ConfJ \On;
        ConfL \On;
        MoveAbsJ home\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via01_01\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via01_02\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via01_03\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via01_04\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveJ RelTool(S1_rt,0,0,-40.000), v300, fine, tTorch\WObj:=wobjTrunk;
        MoveL S1_rt, v300, fine, tTorch\WObj:=wobjTrunk;
        SetDO doWeld, 1;
        MoveC S2_via, S2_rt, v20, fine, tTorch\WObj:=wobjTrunk;
        SetDO doWeld, 0;
        WaitTime 0.300;
        MoveL RelTool(S2_rt,0,0,-40.000), v20, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via03_01\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via03_02\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via03_03\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via03_04\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via03_05\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ home2\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
    ENDPROC
ENDMODULE
