<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.10" tiledversion="1.10.2" name="tiles" tilewidth="16" tileheight="16" tilecount="12" columns="6">
 <image source="tiles.png" width="96" height="32"/>
 <tile id="0" type="ground">
  <properties>
   <property name="solid" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="1" type="wall">
  <properties>
   <property name="solid" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="2" type="plank">
  <properties>
   <property name="one-way" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="3" type="grass"/>
 <tile id="4" type="door-top"/>
 <tile id="5" type="door-bottom"/>
 <tile id="6" type="player"/>
 <tile id="7" type="player-run"/>
 <tile id="8" type="player-jump"/>
 <tile id="9" type="coin"/>
 <tile id="10" type="walker"/>
 <tile id="11" type="walker-step"/>
</tileset>
