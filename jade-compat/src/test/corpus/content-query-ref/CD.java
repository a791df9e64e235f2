import jade.content.*;
import jade.util.leap.List;

/** A bean of the music shop's ontology. */
public class CD extends Item {
    private String title;
    private List tracks;

    public String getTitle() {
        return title;
    }

    public void setTitle(String title) {
        this.title = title;
    }

    public List getTracks() {
        return tracks;
    }

    public void setTracks(List tracks) {
        this.tracks = tracks;
    }
}
