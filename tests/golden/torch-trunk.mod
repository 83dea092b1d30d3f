MODULE TorchTrunk
    ! generator: gen-rapid 0.1.0
    ! cell: torch-trunk.yaml
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
    ! moves: 19
    ! min clearance (mm): 10.0
    ! estimated time (s): 32.99
    ! cycle: open: the routine ends at home2, not where it starts (home); motion.cycle: true closes it
    ! zoned vias: 0 of 10 (via zone fine)
    ! the paper's method alone: 20 moves, 33.42 s

    PERS tooldata tTorch := [TRUE,[[116.673,0.000,336.673],[0.923879539,0.000000000,0.382683416,0.000000000]],[2.500,[0.000,0.000,120.000],[1,0,0,0],0,0,0]];
    PERS wobjdata wobjTrunk := [FALSE,TRUE,"",[[-830.000,-380.000,100.000],[1.000000000,0.000000000,0.000000000,0.000000000]],[[0,0,0],[1,0,0,0]]];

    CONST jointtarget home := [[90.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_01 := [[64.688,-28.219,20.250,3.482,37.473,-50.131],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_02 := [[59.980,-32.863,18.051,3.610,37.746,-51.963],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_03 := [[53.241,-28.044,20.098,4.619,39.912,-66.491],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_04 := [[40.623,-7.124,36.148,7.984,47.133,-114.932],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget L1_rt := [[330.000,280.000,0.000],[0.183012701,-0.683012702,-0.683012702,-0.183012701],[0,0,-2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget L2_rt := [[330.000,630.000,0.000],[0.183012701,-0.683012702,-0.683012702,-0.183012701],[0,0,-2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_01 := [[13.000,14.000,11.000,3.591,65.501,-168.886],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_02 := [[0.000,1.000,-2.000,0.000,65.501,-180.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_03 := [[-25.000,26.000,23.000,-6.882,65.501,-201.299],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget R1_rt := [[1330.000,630.000,0.000],[0.183012701,-0.683012702,-0.683012702,-0.183012701],[-1,-1,-3,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget R2_rt := [[1330.000,280.000,0.000],[0.183012701,-0.683012702,-0.683012702,-0.183012701],[-1,-1,-3,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_01 := [[-43.025,-26.299,20.460,-5.728,42.292,-111.742],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_02 := [[-52.000,-37.000,19.000,-4.365,39.366,-85.149],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_03 := [[-68.355,-21.476,15.783,-2.922,36.271,-57.007],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget home2 := [[-90.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        ConfJ \On;
        ConfL \On;
        MoveAbsJ home\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via01_01\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via01_02\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via01_03\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via01_04\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveJ RelTool(L1_rt,0,0,-40.000), v300, fine, tTorch\WObj:=wobjTrunk;
        MoveL L1_rt, v300, fine, tTorch\WObj:=wobjTrunk;
        SetDO doWeld, 1;
        MoveL L2_rt, v50, fine, tTorch\WObj:=wobjTrunk;
        SetDO doWeld, 0;
        MoveL RelTool(L2_rt,0,0,-40.000), v50, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via03_01\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via03_02\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via03_03\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveJ RelTool(R1_rt,0,0,-40.000), v300, fine, tTorch\WObj:=wobjTrunk;
        MoveL R1_rt, v300, fine, tTorch\WObj:=wobjTrunk;
        SetDO doWeld, 1;
        MoveL R2_rt, v50, fine, tTorch\WObj:=wobjTrunk;
        SetDO doWeld, 0;
        MoveL RelTool(R2_rt,0,0,-40.000), v50, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via05_01\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via05_02\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via05_03\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ home2\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
    ENDPROC
ENDMODULE
