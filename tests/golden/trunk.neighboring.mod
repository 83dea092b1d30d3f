MODULE TrunkWeld
    ! generator: gen-rapid 0.1.0
    ! cell: trunk.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: neighboring
    ! grid (deg): 1.000
    ! clearance (mm): 10.0
    ! base: [0.0, -850.0, 0.0] yaw: 90.000
    ! moves: 17
    ! min clearance (mm): 10.0
    ! estimated time (s): 13.01
    ! cycle: open: the routine ends at F, not where it starts (A); motion.cycle: true closes it
    ! zoned vias: 0 of 12 (via zone fine)

    CONST jointtarget A := [[90.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_01 := [[62.281,-0.031,-7.875,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_02 := [[52.053,-1.860,-7.974,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_03 := [[44.024,2.009,-6.969,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_04 := [[39.000,7.000,-2.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget B := [[30.000,20.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget C := [[25.000,15.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_01 := [[7.094,15.000,5.117,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_02 := [[-7.092,15.000,5.120,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget D := [[-25.000,15.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget E := [[-30.000,20.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_01 := [[-34.047,16.648,3.172,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_02 := [[-42.000,9.000,-6.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_03 := [[-43.906,10.359,-7.906,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_04 := [[-47.516,10.918,-9.596,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_05 := [[-55.340,8.430,-9.943,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_06 := [[-60.000,8.000,-10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget F := [[-90.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ A\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_03\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_04\NoEOffs, v300, fine, tool0;
        MoveAbsJ B\NoEOffs, v300, fine, tool0;
        MoveAbsJ C\NoEOffs, v300, fine, tool0;
        MoveAbsJ via03_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via03_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ D\NoEOffs, v300, fine, tool0;
        MoveAbsJ E\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_03\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_04\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_05\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_06\NoEOffs, v300, fine, tool0;
        MoveAbsJ F\NoEOffs, v300, fine, tool0;
    ENDPROC
ENDMODULE
