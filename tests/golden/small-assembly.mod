MODULE SmallAssembly
    ! generator: gen-rapid 0.1.0
    ! cell: small-assembly.yaml
    ! model: irb120_3_58 (ABB IRB 120-3/0.58, built into gen-rapid)
    ! urdf: irb120_3_58.urdf
    ! controller: irb120_3_58.controller.yaml
    ! coupling: serial (axes 1..6 = URDF joints 1..6)
    ! planner: extensile
    ! grid (deg): 1.000
    ! clearance (mm): 5.0
    ! base: [0.0, 0.0, 750.0] yaw: 0.000
    ! tool: tGrip120 (declared below; collision shapes: housing, finger_a, finger_b)
    ! wobj: wobjTable (declared below; robtargets are in its user frame)
    ! frames: robtargets and the user frame are given in the cell frame; they mean the cell's poses only if the controller's base frame is the base and yaw above
    ! moves: 8
    ! min clearance (mm): 5.7
    ! estimated time (s): 6.04
    ! cycle: closed: the routine ends where it starts; its time is a cycle time
    ! zoned vias: 0 of 1 (via zone fine)

    PERS tooldata tGrip120 := [TRUE,[[0.000,0.000,110.000],[1.000000000,0.000000000,0.000000000,0.000000000]],[0.800,[0.000,0.000,40.000],[1,0,0,0],0,0,0]];
    PERS wobjdata wobjTable := [FALSE,TRUE,"",[[0.000,0.000,750.000],[1.000000000,0.000000000,0.000000000,0.000000000]],[[0,0,0],[1,0,0,0]]];

    CONST jointtarget home := [[0.000,0.000,0.000,0.000,60.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget above_pick_rt := [[350.000,-250.000,120.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pick_rt := [[350.000,-250.000,70.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget lift_rt := [[350.000,-250.000,120.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_01 := [[3.920,16.371,-10.689,0.000,41.626,185.016],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget above_place_rt := [[350.000,230.000,150.000],[0.000000000,1.000000000,0.000000000,0.000000000],[0,0,2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget place_rt := [[350.000,230.000,105.000],[0.000000000,1.000000000,0.000000000,0.000000000],[0,0,2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget leave_rt := [[350.000,230.000,150.000],[0.000000000,1.000000000,0.000000000,0.000000000],[0,0,2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget home2 := [[0.000,0.000,0.000,0.000,60.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        ConfJ \On;
        ConfL \On;
        MoveAbsJ home\NoEOffs, v500, fine, tGrip120\WObj:=wobjTable;
        MoveJ above_pick_rt, v500, fine, tGrip120\WObj:=wobjTable;
        MoveJ pick_rt, v100, fine, tGrip120\WObj:=wobjTable;
        MoveJ lift_rt, v200, fine, tGrip120\WObj:=wobjTable;
        MoveAbsJ via04_01\NoEOffs, v500, fine, tGrip120\WObj:=wobjTable;
        MoveJ above_place_rt, v500, fine, tGrip120\WObj:=wobjTable;
        MoveJ place_rt, v50, fine, tGrip120\WObj:=wobjTable;
        MoveJ leave_rt, v200, fine, tGrip120\WObj:=wobjTable;
        MoveAbsJ home2\NoEOffs, v500, fine, tGrip120\WObj:=wobjTable;
    ENDPROC
ENDMODULE
