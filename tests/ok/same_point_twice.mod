MODULE Dup
    ! generator: gen-rapid 0.1.0
    ! cell: same_point_twice.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: neighboring
    ! grid (deg): 0.500
    ! clearance (mm): 10.0
    ! base: [0.0, 0.0, 0.0] yaw: 0.000
    ! moves: 1
    ! min clearance (mm): none (no obstacles)
    ! estimated time (s): 0.00
    ! cycle: closed: the routine ends where it starts; its time is a cycle time
    ! zoned vias: 0 of 0 (via zone fine)
    ! the paper's method alone: 1 move, 0.00 s

    CONST jointtarget P1 := [[10.500,3.250,0.125,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget P2 := [[10.500,3.250,0.125,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ P1\NoEOffs, v300, fine, tool0;
        MoveAbsJ P2\NoEOffs, v300, fine, tool0;
    ENDPROC
ENDMODULE
