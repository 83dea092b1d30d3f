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
    ! moves: 15
    ! min clearance (mm): 10.0
    ! estimated time (s): 32.56
    ! zoned vias: 0 of 10 (via zone fine)

    PERS tooldata tTorch := [TRUE,[[116.673,0.000,336.673],[0.923879539,0.000000000,0.382683416,0.000000000]],[2.500,[0.000,0.000,120.000],[1,0,0,0],0,0,0]];
    PERS wobjdata wobjTrunk := [FALSE,TRUE,"",[[-830.000,-380.000,100.000],[1.000000000,0.000000000,0.000000000,0.000000000]],[[0,0,0],[1,0,0,0]]];

    CONST jointtarget home := [[90.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_01 := [[62.000,-31.000,20.000,3.339,36.397,-47.847],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_02 := [[57.313,-31.844,18.234,3.598,36.894,-51.558],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_03 := [[56.000,-31.000,19.000,3.821,37.320,-54.751],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_04 := [[39.101,-10.146,23.444,6.562,42.573,-94.033],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget L1 := [[33.816,20.956,52.462,10.745,50.586,-153.966],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget L1_rt := [[330.000,280.000,0.000],[0.183012701,-0.683012702,-0.683012702,-0.183012701],[0,0,-2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget L2 := [[24.514,44.727,39.355,6.833,64.506,-159.180],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget L2_rt := [[330.000,630.000,0.000],[0.183012701,-0.683012702,-0.683012702,-0.183012701],[0,0,-2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_01 := [[14.957,23.053,12.097,4.169,64.506,-167.297],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_02 := [[0.000,8.000,-3.000,0.000,64.506,-180.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_03 := [[-24.602,32.793,21.881,-6.833,64.506,-200.820],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget R1 := [[-24.514,44.727,39.355,-6.833,64.506,-200.820],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget R1_rt := [[1330.000,630.000,0.000],[0.183012701,-0.683012702,-0.683012702,-0.183012701],[-1,-1,-3,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget R2 := [[-33.816,20.956,52.462,-10.745,50.586,-206.034],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget R2_rt := [[1330.000,280.000,0.000],[0.183012701,-0.683012702,-0.683012702,-0.183012701],[-1,-1,-3,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_01 := [[-41.119,-24.876,20.046,-5.546,40.626,-106.349],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_02 := [[-52.000,-37.000,19.000,-3.989,37.642,-76.480],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_03 := [[-67.313,-22.648,18.258,-2.975,35.701,-57.054],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget home2 := [[-90.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ home\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via01_01\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via01_02\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via01_03\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via01_04\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ L1\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ L2\NoEOffs, v50, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via03_01\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via03_02\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via03_03\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ R1\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ R2\NoEOffs, v50, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via05_01\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via05_02\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via05_03\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveAbsJ home2\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
    ENDPROC
ENDMODULE
