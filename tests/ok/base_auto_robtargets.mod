MODULE AutoTcp
    ! generator: gen-rapid 0.1.0
    ! cell: base_auto_robtargets.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: extensile
    ! grid (deg): 2.000
    ! clearance (mm): 10.0
    ! base: [155.0, -5.0, 0.0] yaw: 0.000
    ! tool: tGripper (declared below; collision shapes: housing)
    ! wobj: wobj0 (robtargets are in the world frame)
    ! frames: robtargets and the user frame are given in the cell frame; they mean the cell's poses only if the controller's base frame is the base and yaw above
    ! moves: 2
    ! min clearance (mm): 367.1
    ! estimated time (s): 4.03
    ! cycle: open: the routine ends at C, not where it starts (A); motion.cycle: true closes it
    ! zoned vias: 0 of 0 (via zone fine)

    PERS tooldata tGripper := [TRUE,[[0.000,0.000,180.000],[1.000000000,0.000000000,0.000000000,0.000000000]],[1.000,[0.000,0.000,0.000],[1,0,0,0],0,0,0]];

    CONST robtarget A_rt := [[900.000,-300.000,400.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget B_rt := [[900.000,300.000,400.000],[0.000000000,1.000000000,0.000000000,0.000000000],[0,0,2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget C_rt := [[600.000,0.000,700.000],[0.000000000,1.000000000,0.000000000,0.000000000],[0,0,2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        ConfJ \On;
        ConfL \On;
        MoveJ A_rt, v300, fine, tGripper;
        MoveJ B_rt, v300, fine, tGripper;
        MoveJ C_rt, v300, fine, tGripper;
    ENDPROC
ENDMODULE
