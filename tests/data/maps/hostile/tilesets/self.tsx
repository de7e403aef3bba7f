<?xml version="1.0" encoding="UTF-8"?>
<tileset source="self.tsx" name="self" tilewidth="16" tileheight="16" tilecount="8" columns="4">
</tileset>
