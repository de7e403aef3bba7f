<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.8" tiledversion="1.8.2" name="sprites" tilewidth="16" tileheight="16" tilecount="16" columns="8">
 <image source="sprites.png" width="128" height="32"/>
 <tile id="0" type="player"/>
 <tile id="1" type="player-run"/>
 <tile id="2" type="player-jump"/>
 <tile id="3" type="walker"/>
 <tile id="4" type="walker-step"/>
 <tile id="5" type="ship"/>
 <tile id="6" type="enemy-ship"/>
 <tile id="7" type="enemy-ship-flap"/>
 <tile id="8" type="bullet"/>
 <tile id="9" type="box"/>
 <tile id="10" type="coin"/>
 <tile id="11" type="goal"/>
 <tile id="12" type="moving-platform"/>
 <tile id="13" type="ball"/>
 <tile id="14" type="spikes"/>
 <tile id="15" type="explosion"/>
</tileset>
