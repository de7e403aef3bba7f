<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.8" tiledversion="1.8.2" name="terrain" tilewidth="16" tileheight="16" tilecount="8" columns="4">
 <image source="../images/terrain.png" width="64" height="32"/>
 <tile id="0">
  <properties>
   <property name="solid" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="1">
  <properties>
   <property name="collision" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="2">
  <properties>
   <property name="collides" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="3">
  <objectgroup draworder="index" id="2">
   <object id="1" x="0" y="8" width="16" height="8"/>
  </objectgroup>
 </tile>
 <tile id="4">
  <properties>
   <property name="solid" type="bool" value="false"/>
  </properties>
 </tile>
 <tile id="5">
  <objectgroup draworder="index" id="2"/>
 </tile>
 <tile id="7">
  <properties>
   <property name="collision" value="TRUE"/>
   <property name="damage" type="int" value="3"/>
  </properties>
 </tile>
 <tile id="6" type="ladder">
  <properties>
   <property name="climbable" type="bool" value="true"/>
  </properties>
  <animation>
   <frame tileid="6" duration="100"/>
  </animation>
 </tile>
</tileset>
