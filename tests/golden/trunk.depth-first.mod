MODULE TrunkWeld
    ! generator: gen-rapid 0.1.0
    ! cell: trunk.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: depth-first
    ! grid (deg): 1.000
    ! clearance (mm): 10.0
    ! base: [0.0, -850.0, 0.0] yaw: 90.000
    ! moves: 11
    ! min clearance (mm): 10.0
    ! estimated time (s): 14.50
    ! cycle: open: the routine ends at F, not where it starts (A); motion.cycle: true closes it
    ! zoned vias: 0 of 6 (via zone fine)

    CONST jointtarget A := [[90.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_01 := [[88.594,-0.977,-7.813,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_02 := [[30.000,-1.000,-8.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget B := [[30.000,20.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget C := [[25.000,15.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_01 := [[23.438,15.000,5.156,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_02 := [[-24.622,15.000,5.040,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget D := [[-25.000,15.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget E := [[-30.000,20.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_01 := [[-30.469,-0.836,-7.859,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_02 := [[-89.535,-0.991,-7.936,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget F := [[-90.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ A\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ B\NoEOffs, v300, fine, tool0;
        MoveAbsJ C\NoEOffs, v300, fine, tool0;
        MoveAbsJ via03_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via03_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ D\NoEOffs, v300, fine, tool0;
        MoveAbsJ E\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ F\NoEOffs, v300, fine, tool0;
    ENDPROC
ENDMODULE
