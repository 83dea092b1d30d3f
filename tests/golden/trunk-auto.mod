MODULE TrunkWeldAuto
    ! generator: gen-rapid 0.1.0
    ! cell: trunk-auto.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: extensile
    ! grid (deg): 1.000
    ! clearance (mm): 10.0
    ! base: [-5.0, -965.0, 0.0] yaw: 90.000
    ! moves: 10
    ! min clearance (mm): 10.0
    ! estimated time (s): 12.96
    ! cycle: open: the routine ends at F, not where it starts (A); motion.cycle: true closes it
    ! zoned vias: 0 of 5 (via zone fine)

    CONST jointtarget A := [[82.427,0.249,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_01 := [[42.000,13.000,-13.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_02 := [[27.586,27.514,1.582,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget B := [[27.006,30.553,6.300,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget C := [[22.325,25.605,6.979,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_01 := [[-4.628,19.532,0.539,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget D := [[-22.789,26.021,6.830,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget E := [[-27.436,31.080,6.078,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_01 := [[-37.000,17.000,-7.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_02 := [[-56.939,0.775,-20.376,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget F := [[-82.513,1.198,-0.010,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ A\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ B\NoEOffs, v300, fine, tool0;
        MoveAbsJ C\NoEOffs, v300, fine, tool0;
        MoveAbsJ via03_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ D\NoEOffs, v300, fine, tool0;
        MoveAbsJ E\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ F\NoEOffs, v300, fine, tool0;
    ENDPROC
ENDMODULE
