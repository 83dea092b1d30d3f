MODULE TcpCase
    ! generator: gen-rapid 0.1.0
    ! cell: tool_wobj_robtargets.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: extensile
    ! grid (deg): 1.000
    ! clearance (mm): 10.0
    ! base: [0.0, 0.0, 0.0] yaw: 0.000
    ! tool: tTorch (declared below; collision shapes: neck)
    ! wobj: wobjTable (declared below; robtargets are in its user frame)
    ! frames: robtargets and the user frame are given in the cell frame; they mean the cell's poses only if the controller's base frame is the base and yaw above
    ! moves: 2
    ! min clearance (mm): 183.3
    ! estimated time (s): 4.64
    ! cycle: open: the routine ends at W2, not where it starts (P1); motion.cycle: true closes it
    ! zoned vias: 0 of 0 (via zone fine)

    PERS tooldata tTorch := [TRUE,[[0.000,0.000,250.000],[0.965925836,0.000000000,0.258819010,0.000000000]],[1.000,[0.000,0.000,0.000],[1,0,0,0],0,0,0]];
    PERS wobjdata wobjTable := [FALSE,TRUE,"",[[700.000,-200.000,400.000],[1.000000000,0.000000000,0.000000000,0.000000000]],[[0,0,0],[1,0,0,0]]];

    CONST jointtarget P1 := [[-30.000,0.000,0.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget W1_rt := [[100.000,200.000,150.000],[0.000000000,0.000000000,1.000000000,0.000000000],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget W2_rt := [[200.000,300.000,150.000],[0.000000000,0.000000000,1.000000000,0.000000000],[0,-1,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        ConfJ \On;
        ConfL \On;
        MoveAbsJ P1\NoEOffs, v300, fine, tTorch\WObj:=wobjTable;
        MoveJ W1_rt, v300, fine, tTorch\WObj:=wobjTable;
        MoveJ W2_rt, v100, fine, tTorch\WObj:=wobjTable;
    ENDPROC
ENDMODULE
