MODULE RevisitCycle
    ! generator: gen-rapid 0.1.0
    ! cell: revisit_cycle.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: extensile
    ! grid (deg): 1.000
    ! clearance (mm): 10.0
    ! base: [0.0, -850.0, 0.0] yaw: 90.000
    ! moves: 15
    ! min clearance (mm): 10.0
    ! estimated time (s): 38.32
    ! cycle: closed: the routine ends where it starts; its time is a cycle time
    ! zoned vias: 0 of 8 (via zone fine)
    ! the paper's method alone: 15 moves, 38.77 s

    CONST jointtarget A := [[90.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_01 := [[49.000,-3.000,-12.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_02 := [[30.445,15.648,6.625,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget B := [[30.000,20.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_01 := [[-2.578,15.547,2.969,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_01 := [[3.188,15.000,2.828,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget C := [[25.000,15.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_01 := [[-3.188,15.000,2.828,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget D := [[-25.000,15.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_01 := [[-56.094,-14.531,-16.563,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget F := [[-90.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via06_01 := [[-22.418,14.076,-20.424,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via07_01 := [[56.094,-14.531,-16.563,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ A\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ B\NoEOffs, v300, fine, tool0;
        MoveAbsJ via02_01\NoEOffs, v100, fine, tool0;
        MoveAbsJ D\NoEOffs, v100, fine, tool0;
        MoveAbsJ via03_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ C\NoEOffs, v300, fine, tool0;
        MoveAbsJ via04_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ D\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ F\NoEOffs, v300, fine, tool0;
        MoveAbsJ via06_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ C\NoEOffs, v300, z10, tool0;
        MoveAbsJ via07_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ A\NoEOffs, v300, fine, tool0;
    ENDPROC
ENDMODULE
