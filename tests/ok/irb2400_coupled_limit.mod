MODULE Irb2400Limit
    ! generator: gen-rapid 0.1.0
    ! cell: irb2400_coupled_limit.yaml
    ! model: irb2400_12_155 (ABB IRB 2400-12/1.55, built into gen-rapid)
    ! urdf: irb2400_12_155.urdf
    ! controller: irb2400_12_155.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: extensile
    ! grid (deg): 2.000
    ! clearance (mm): 10.0
    ! base: [0.0, 0.0, 0.0] yaw: 0.000
    ! moves: 5
    ! min clearance (mm): 10.1
    ! estimated time (s): 14.80
    ! cycle: open: the routine ends at P3, not where it starts (P1); motion.cycle: true closes it
    ! zoned vias: 0 of 3 (via zone fine)

    CONST jointtarget P1 := [[-40.000,60.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_01 := [[-18.000,34.000,-24.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_02 := [[1.125,18.813,-39.281,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_03 := [[38.315,54.804,-5.032,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget P2 := [[40.000,60.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget P3 := [[20.000,-30.000,-45.000,0.000,45.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ P1\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_03\NoEOffs, v300, fine, tool0;
        MoveAbsJ P2\NoEOffs, v300, fine, tool0;
        MoveAbsJ P3\NoEOffs, v300, fine, tool0;
    ENDPROC
ENDMODULE
