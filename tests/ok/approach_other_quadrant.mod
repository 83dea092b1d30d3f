MODULE QuadrantCase
    ! generator: gen-rapid 0.1.0
    ! cell: approach_other_quadrant.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: extensile
    ! grid (deg): 1.000
    ! clearance (mm): 10.0
    ! base: [0.0, 0.0, 0.0] yaw: 0.000
    ! tool: tGrip (declared below; collision shapes: body)
    ! wobj: wobj0 (robtargets are in the world frame)
    ! frames: robtargets and the user frame are given in the cell frame; they mean the cell's poses only if the controller's base frame is the base and yaw above
    ! moves: 8
    ! min clearance (mm): 49.8
    ! estimated time (s): 12.04
    ! cycle: open: the routine ends at home2, not where it starts (home); motion.cycle: true closes it
    ! zoned vias: 0 of 0 (via zone fine)

    PERS tooldata tGrip := [TRUE,[[0.000,0.000,150.000],[1.000000000,0.000000000,0.000000000,0.000000000]],[1.000,[0.000,0.000,0.000],[1,0,0,0],0,0,0]];

    CONST jointtarget home := [[0.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget P1_app := [[700.000,50.000,486.603],[0.223463188,-0.833976055,-0.487336274,-0.130581393],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget P1_rt := [[700.000,100.000,400.000],[0.223463188,-0.833976055,-0.487336274,-0.130581393],[-1,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget P2_via := [[737.500,110.048,400.000],[0.223463188,-0.833976055,-0.487336274,-0.130581393],[-1,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget P2_rt := [[764.952,212.500,400.000],[0.223463188,-0.833976055,-0.487336274,-0.130581393],[0,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget P3_app := [[700.000,50.000,486.603],[0.223463188,-0.833976055,-0.487336274,-0.130581393],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget P3_rt := [[700.000,100.000,400.000],[0.223463188,-0.833976055,-0.487336274,-0.130581393],[-1,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget P3_ret := [[700.000,50.000,486.603],[0.223463188,-0.833976055,-0.487336274,-0.130581393],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget home2 := [[20.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        ConfJ \On;
        ConfL \On;
        MoveAbsJ home\NoEOffs, v300, fine, tGrip;
        MoveJ P1_app, v300, fine, tGrip;
        MoveL P1_rt, v300, fine, tGrip;
        SetDO doGrip, 1;
        MoveC P2_via, P2_rt, v50, fine, tGrip;
        SetDO doGrip, 0;
        MoveL RelTool(P2_rt,0,0,-100.000), v50, fine, tGrip;
        MoveJ P3_app, v300, fine, tGrip;
        MoveL P3_rt, v300, fine, tGrip;
        MoveL P3_ret, v300, fine, tGrip;
        MoveAbsJ home2\NoEOffs, v300, fine, tGrip;
    ENDPROC
ENDMODULE
